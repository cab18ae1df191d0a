//! Lane borders and centres at some s, computed without allocating (the engine asks for them
//! every step of every entity): the road's lazy border iterator, searched for one lane.

use opendrive::{LaneBorders, Road};

/// t of the inner and outer border and of the centre (as esmini rounds it, see
/// `LaneBorders::center`) of lane `lane_id` in section `section` at road `s`; `None` when the
/// lane does not exist. Centre lane: all at the lane offset.
pub(crate) fn lane_borders(road: &Road, section: usize, lane_id: i32, s: f64) -> Option<LaneBorders> {
    if lane_id == 0 {
        road.lane_sections.get(section)?;
        let base = road.lane_offset_at(s);
        return Some(LaneBorders { inner: base, outer: base, center: base });
    }
    // the road's lazy border iterator: the same sums in the same order, nothing allocated
    road.side_border_iter(section, lane_id > 0, s).find(|(id, _)| *id == lane_id).map(|(_, b)| b)
}

/// t of the centre of lane `lane_id` at `s` (section looked up).
pub(crate) fn lane_center_t(road: &Road, lane_id: i32, s: f64) -> Option<f64> {
    lane_borders(road, road.section_index_at(s), lane_id, s).map(|b| b.center)
}

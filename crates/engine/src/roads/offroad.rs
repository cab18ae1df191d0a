//! Whether a road position counts as off the road, as esmini's OffroadCondition sees it: outside
//! the lanes of a real type on that side. Lanes of type `none` (often wide verges at the edge of
//! a road) do not count as road.

use opendrive::{LaneType, Road};

use super::lane_geometry::lane_borders;

/// `t` (from the reference line, + left) is further out than the outermost border of a lane that
/// is not of type `none` on its side of the centre lane: esmini's Position::IsOffRoad measures
/// from the centre lane (t less the road's lane offset) against the widths summed from it.
pub(crate) fn is_off_road(road: &Road, s: f64, t: f64) -> bool {
    let from_centre = t - road.lane_offset_at(s);
    from_centre.abs() > road_width(road, s, from_centre >= 0.0) + 1e-9
}

/// Distance from the centre lane to the outer border of the outermost non-`none` lane of a side.
pub(crate) fn road_width(road: &Road, s: f64, left: bool) -> f64 {
    let section = road.section_index_at(s);
    let Some(sec) = road.lane_sections.get(section) else { return 0.0 };
    let base = road.lane_offset_at(s);
    let lanes = if left { &sec.left } else { &sec.right };
    lanes.iter().filter(|l| l.kind != LaneType::None).filter_map(|l| lane_borders(road, section, l.id, s)).map(|b| (b.outer - base).abs()).fold(0.0, f64::max)
}

//! Whether a road position counts as off the road, as esmini's OffroadCondition sees it: outside
//! the lanes of a real type on that side. Lanes of type `none` (often wide verges at the edge of
//! a road) do not count as road.

use opendrive::{LaneType, Road};

use super::lane_geometry::lane_borders;

/// `t` (from the reference line, + left) is further out than the outermost border of a lane that
/// is not of type `none` on the side `t` lies on. The lane offset is not part of the comparison
/// (widths are summed from the centre lane), as in esmini.
pub(crate) fn is_off_road(road: &Road, s: f64, t: f64) -> bool {
    t.abs() > road_width(road, s, t >= 0.0) + 1e-9
}

/// Distance from the centre lane to the outer border of the outermost non-`none` lane of a side.
pub(crate) fn road_width(road: &Road, s: f64, left: bool) -> f64 {
    let section = road.section_index_at(s);
    let Some(sec) = road.lane_sections.get(section) else { return 0.0 };
    let base = road.lane_offset_at(s);
    let lanes = if left { &sec.left } else { &sec.right };
    lanes
        .iter()
        .filter(|l| l.kind != LaneType::None)
        .filter_map(|l| lane_borders(road, section, l.id, s))
        .map(|(_, outer)| (outer - base).abs())
        .fold(0.0, f64::max)
}

//! Lane borders and centres at some s, computed without allocating (the engine asks for them
//! every step of every entity; `opendrive`'s own helpers build vectors).

use opendrive::model::poly::record_at;
use opendrive::{Lane, Road};

/// t of the inner and outer border of lane `lane_id` in section `section` at road `s`;
/// `None` when the lane does not exist. Centre lane: both at the lane offset.
pub(crate) fn lane_borders(road: &Road, section: usize, lane_id: i32, s: f64) -> Option<(f64, f64)> {
    let sec = road.lane_sections.get(section)?;
    let base = road.lane_offset_at(s);
    if lane_id == 0 {
        return Some((base, base));
    }
    let (lanes, sign): (&[Lane], f64) = if lane_id > 0 { (&sec.left, 1.0) } else { (&sec.right, -1.0) };
    let ds = s - sec.s;
    let mut inner = base;
    for lane in lanes {
        let outer = if !lane.widths.is_empty() {
            inner + sign * record_at(&lane.widths, ds).map_or(0.0, |r| r.value(ds - r.s))
        } else if let Some(b) = record_at(&lane.borders, ds) {
            base + b.value(ds - b.s)
        } else {
            inner
        };
        if lane.id == lane_id {
            return Some((inner, outer));
        }
        inner = outer;
    }
    None
}

/// t of the centre of lane `lane_id` at `s` (section looked up).
pub(crate) fn lane_center_t(road: &Road, lane_id: i32, s: f64) -> Option<f64> {
    let (a, b) = lane_borders(road, road.section_index_at(s), lane_id, s)?;
    Some(0.5 * (a + b))
}

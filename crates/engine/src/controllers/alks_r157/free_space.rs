//! The free-space gap between two entities in road coordinates, as the ALKS R157 models measure
//! it (esmini's Object::FreeSpaceDistanceObjectRoadLane with CS_ROAD): every corner of both
//! bounding boxes is mapped onto the road (Position::XYZ2TrackPos), and of the sixteen
//! corner-to-corner deltas (Position::Delta) the smallest along s and the smallest across t are
//! the gaps; a corner of the first box lying between the second's corners along s (or t) makes
//! that gap zero, and overlapping boxes are zero in both. On a curved road this differs from
//! turning the boxes rigidly into the road frame.

use super::distance_models::esmini_sign;
use crate::conditions::distance::{boxes_overlap, corners};
use crate::entities::Entity;
use crate::roads::locate::world_to_lane;
use opendrive::RoadNetwork;

/// The corners in esmini's order (first quadrant first, counter-clockwise) mapped to (s, t) on
/// `road`. A corner past the road's end is where the road network puts it (XYZ2TrackPos
/// follows the links: on a closed loop it is near s = 0 again, which makes the deltas change
/// sign); `None` where a corner lies on another road (esmini then measures along a road path,
/// which this does not model: the object is left out, as where esmini's measurement fails).
fn road_corners(net: &RoadNetwork, e: &Entity, road: usize, hint_s: f64) -> Option<[(f64, f64); 4]> {
    let [fl, fr, rr, rl] = corners(e);
    let mut out = [(0.0, 0.0); 4];
    for (k, (x, y)) in [fl, rl, rr, fr].into_iter().enumerate() {
        let p = world_to_lane(net, x, y, Some((road, hint_s)))?;
        if p.road != road {
            return None;
        }
        out[k] = (p.s, p.t);
    }
    Some(out)
}

/// Gaps (along s in `a`'s driving direction `dir`, across t as t grows) from `a` to `b`, both
/// on road `road`; `None` where esmini's measurement fails (a corner off the road).
pub(super) fn free_space_road(net: &RoadNetwork, a: &Entity, b: &Entity, road: usize, dir: f64) -> Option<(f64, f64)> {
    if boxes_overlap(&corners(a), &corners(b)) {
        return Some((0.0, 0.0));
    }
    let hint = a.lane.map_or(0.0, |l| l.s);
    let ca = road_corners(net, a, road, hint)?;
    let cb = road_corners(net, b, road, b.lane.map_or(hint, |l| l.s))?;
    let mut ds = [[0.0; 4]; 4];
    let mut dt = [[0.0; 4]; 4];
    let (mut min_ds, mut min_dt) = (0.0f64, 0.0f64);
    for (i, &(sa, ta)) in ca.iter().enumerate() {
        for (j, &(sb, tb)) in cb.iter().enumerate() {
            // RoadPath::Calculate on one road: the s difference, turned for facing against s
            ds[i][j] = (sb - sa) * dir;
            dt[i][j] = tb - ta;
            if (i == 0 && j == 0) || ds[i][j].abs() < min_ds.abs() {
                min_ds = ds[i][j];
            }
            if (i == 0 && j == 0) || dt[i][j].abs() < min_dt.abs() {
                min_dt = dt[i][j];
            }
        }
    }
    let mixed = |row: &[f64; 4]| row.iter().any(|&v| esmini_sign(v) != esmini_sign(row[0]));
    if ds.iter().any(mixed) {
        min_ds = 0.0;
    }
    if dt.iter().any(mixed) {
        min_dt = 0.0;
    }
    Some((min_ds, min_dt))
}

//! The free-space gap between two entities in road coordinates (esmini's
//! Object::FreeSpaceDistanceObjectRoadLane with CS_ROAD), as the ALKS R157 models and the
//! RelativeClearanceCondition measure it: every corner of both bounding boxes is mapped onto the
//! road (Position::XYZ2TrackPos), and of the sixteen corner-to-corner deltas (Position::Delta)
//! the smallest along s and the smallest across t are the gaps; a corner of the first box lying
//! between the second's corners along s (or t) makes that gap zero, and overlapping boxes are
//! zero in both. On a curved road this differs from turning the boxes rigidly into the road
//! frame. The lane difference esmini reports with it is the one of the last pair of corners
//! compared: the two front right corners.

use crate::conditions::boxes::{boxes_overlap, corners};
use crate::entities::{Entity, EntityKind};
use crate::roads::lane_snap::snap;
use crate::roads::locate::world_to_lane;
use opendrive::{LanePosition, RoadNetwork};

/// What FreeSpaceDistanceObjectRoadLane leaves in its PositionDiff.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FreeSpaceGap {
    /// Gap along s in the first entity's driving direction.
    pub ds: f64,
    /// Gap across t, as t grows.
    pub dt: f64,
    /// The lanes of the front right corners (first entity, second); `None` when the boxes
    /// overlap (esmini then reports a lane difference of 0).
    pub front_right_lanes: Option<(i32, i32)>,
}

/// The corners in esmini's order (first quadrant first, counter-clockwise: front left, rear
/// left, rear right, front right) located on `road`. A corner past the road's end is where the
/// road network puts it (XYZ2TrackPos follows the links: on a closed loop it is near s = 0 again,
/// which makes the deltas change sign); `None` where a corner lies on another road (esmini then
/// measures along a road path, which this does not model). Each corner's lane is the one
/// esmini snaps a position to (LaneSection::GetClosestLaneIdx with the lane types of the
/// measuring entity's position: `sidewalks` for a pedestrian).
fn road_corners(net: &RoadNetwork, e: &Entity, road: usize, hint_s: f64, sidewalks: bool) -> Option<[LanePosition; 4]> {
    located_corners(net, e, road, hint_s, sidewalks, true)
}

/// [`road_corners`], each corner on the road `world_to_lane` puts it on from a start on `road`
/// (`only_road`: `None` where one lies on another road).
fn located_corners(net: &RoadNetwork, e: &Entity, road: usize, hint_s: f64, sidewalks: bool, only_road: bool) -> Option<[LanePosition; 4]> {
    let [fl, fr, rr, rl] = corners(e);
    let mut out = [None; 4];
    for (k, (x, y)) in [fl, rl, rr, fr].into_iter().enumerate() {
        // A copy of the entity's position: its lane is the current one (XYZ2TrackPos).
        let lane_id = e.lane.filter(|l| l.road == road).map_or(0, |l| l.lane_id);
        let mut p = world_to_lane(net, x, y, Some((road, hint_s, lane_id)))?;
        if only_road && p.road != road {
            return None;
        }
        if let Some((lane, offset)) = net.roads.get(p.road).and_then(|r| snap(r, p.section, p.s, p.t, sidewalks)) {
            (p.lane_id, p.offset) = (lane, offset);
        }
        out[k] = Some(p);
    }
    let [a, b, c, d] = out;
    Some([a?, b?, c?, d?])
}

/// Gaps from `a` to `b`, both on road `road`, `a` facing along s when `dir` is +1; `None`
/// where a corner lies off that road.
pub(crate) fn free_space_road(net: &RoadNetwork, a: &Entity, b: &Entity, road: usize, dir: f64) -> Option<FreeSpaceGap> {
    if boxes_overlap(&corners(a), &corners(b)) {
        return Some(FreeSpaceGap { ds: 0.0, dt: 0.0, front_right_lanes: None });
    }
    let hint = a.lane.map_or(0.0, |l| l.s);
    let sidewalks = a.kind == EntityKind::Pedestrian;
    let ca = road_corners(net, a, road, hint, sidewalks)?;
    let cb = road_corners(net, b, road, b.lane.map_or(hint, |l| l.s), sidewalks)?;
    // RoadPath::Calculate on one road: the s difference, turned for facing against s
    gap_of(&ca, &cb, |pa, pb| Some(((pb.s - pa.s) * dir, pb.t - pa.t)))
}

/// The smallest of the sixteen corner-to-corner deltas `delta` gives along s and across t
/// (`None` where one is not found), zero where a corner of the first box lies between the
/// second's.
fn gap_of(ca: &[LanePosition; 4], cb: &[LanePosition; 4], delta: impl Fn(&LanePosition, &LanePosition) -> Option<(f64, f64)>) -> Option<FreeSpaceGap> {
    let mut ds = [[0.0; 4]; 4];
    let mut dt = [[0.0; 4]; 4];
    let (mut min_ds, mut min_dt) = (0.0f64, 0.0f64);
    for (i, pa) in ca.iter().enumerate() {
        for (j, pb) in cb.iter().enumerate() {
            (ds[i][j], dt[i][j]) = delta(pa, pb)?;
            if (i == 0 && j == 0) || ds[i][j].abs() < min_ds.abs() {
                min_ds = ds[i][j];
            }
            if (i == 0 && j == 0) || dt[i][j].abs() < min_dt.abs() {
                min_dt = dt[i][j];
            }
        }
    }
    // esmini's SIGN: −1 below zero, +1 otherwise
    let mixed = |row: &[f64; 4]| row.iter().any(|&v| (v < 0.0) != (row[0] < 0.0));
    if ds.iter().any(mixed) {
        min_ds = 0.0;
    }
    if dt.iter().any(mixed) {
        min_dt = 0.0;
    }
    Some(FreeSpaceGap { ds: min_ds, dt: min_dt, front_right_lanes: Some((ca[3].lane_id, cb[3].lane_id)) })
}

/// [`free_space_road`] where the corners may lie on other roads than `road` (`a`'s), as
/// FreeSpaceDistanceObjectRoadLane has it: each corner is located from `a`'s position
/// (XYZ2TrackPos, the roads connected to it) keeping `a`'s heading, and a pair of corners on
/// two roads is measured by Position::Delta along the road path between them (RoadPath::
/// Calculate in both directions: its length, negative when the path leaves the corner's road
/// behind it, turned again for a heading against the corner's lane's driving direction; across,
/// the t difference, or the sum where the path turns the lane ids around). `None` where a
/// corner is on no road or two corners are not joined by a path (esmini: not measured).
pub(crate) fn free_space_roads(net: &RoadNetwork, a: &Entity, b: &Entity, road: usize) -> Option<FreeSpaceGap> {
    if boxes_overlap(&corners(a), &corners(b)) {
        return Some(FreeSpaceGap { ds: 0.0, dt: 0.0, front_right_lanes: None });
    }
    let hint = a.lane.map_or(0.0, |l| l.s);
    let sidewalks = a.kind == EntityKind::Pedestrian;
    let ca = located_corners(net, a, road, hint, sidewalks, false)?;
    let cb = located_corners(net, b, road, b.lane.map_or(hint, |l| l.s), sidewalks, false)?;
    let h = a.h;
    // the corner position faces against its road (GetHRelative in (pi/2, 3pi/2))
    let backwards = |p: &LanePosition| (h - p.heading).cos() < 0.0;
    gap_of(&ca, &cb, |pa, pb| {
        if pa.road == pb.road {
            return Some(((pb.s - pa.s) * if backwards(pa) { -1.0 } else { 1.0 }, pb.t - pa.t));
        }
        let ra = net.roads.get(pa.road)?;
        let rb = net.roads.get(pb.road)?;
        let path = crate::roads::road_path::path_ends(net, pa.road, pa.s, pa.lane_id, pb.road)?;
        // RoadPath::Calculate's direction_: +1 when the path leaves by the end the corner faces
        let ahead = (path.first_exit == opendrive::ContactPoint::End) != backwards(pa);
        let mut dist = path.length_to(pb.s, rb.length) * if ahead { 1.0 } else { -1.0 };
        // GetHRelativeDrivingDirection in (pi/2, 3pi/2) as an angle difference in [-pi, pi]
        let drive_h = opendrive::driving_direction::driving_heading(ra.rule, pa.lane_id, pa.heading);
        if crate::controllers::looming::view::angle_difference(h, drive_h) > std::f64::consts::FRAC_PI_2 {
            dist = -dist;
        }
        Some((dist, if path.lanes_flip { pb.t + pa.t } else { pb.t - pa.t }))
    })
}

/// Gaps from `a`'s box to the point at (`s`, `t`) on road `road`, `a` facing along s when `dir`
/// is +1: esmini's Object::FreeSpaceDistancePointRoadLane. Each corner's delta to the point
/// (Position::Delta on one road); the gap is the delta smallest in magnitude (the first corner
/// wins ties), and zero only where it and the delta largest in magnitude differ in sign (the
/// other corners are not looked at). `None` where a corner lies off `road`.
pub(crate) fn free_space_point_road(net: &RoadNetwork, a: &Entity, s: f64, t: f64, road: usize, dir: f64) -> Option<(f64, f64)> {
    let hint = a.lane.map_or(s, |l| l.s);
    let ca = road_corners(net, a, road, hint, a.kind == EntityKind::Pedestrian)?;
    let (mut min_ds, mut max_ds, mut min_dt, mut max_dt) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (j, c) in ca.iter().enumerate() {
        let ds = (s - c.s) * dir;
        let dt = t - c.t;
        if j == 0 || ds.abs() < min_ds.abs() {
            min_ds = ds;
        }
        if j == 0 || dt.abs() < min_dt.abs() {
            min_dt = dt;
        }
        if j == 0 || ds.abs() > max_ds.abs() {
            max_ds = ds;
        }
        if j == 0 || dt.abs() > max_dt.abs() {
            max_dt = dt;
        }
    }
    // esmini's SIGN: −1 below zero, +1 otherwise
    let gap = |min: f64, max: f64| if (min < 0.0) != (max < 0.0) { 0.0 } else { min };
    Some((gap(min_ds, max_ds), gap(min_dt, max_dt)))
}

//! The free-space gap between two entities in road coordinates (esmini's
//! Object::FreeSpaceDistanceObjectRoadLane with CS_ROAD), as the ALKS R157 models and the
//! RelativeClearanceCondition measure it: every corner of both bounding boxes is mapped onto the
//! road (Position::XYZ2TrackPos), and of the sixteen corner-to-corner deltas (Position::Delta)
//! the smallest along s and the smallest across t are the gaps; a corner of the first box lying
//! between the second's corners along s (or t) makes that gap zero, and overlapping boxes are
//! zero in both. On a curved road this differs from turning the boxes rigidly into the road
//! frame. The lane difference esmini reports with it is the one of the last pair of corners
//! compared: the two front right corners. Corners on other roads than the entity's are measured
//! along the road path between them, and the DistanceCondition's box-to-point gap
//! (Object::FreeSpaceDistancePointRoadLane) is measured the same way, corner by corner.

use crate::conditions::boxes::{boxes_overlap, corners};
use crate::entities::{Entity, EntityKind};
use crate::roads::junction_entry::entry_connector;
use crate::roads::lane_snap::snap;
use crate::roads::locate::world_to_lane;
use crate::roads::LanePos;
use opendrive::{LanePosition, RoadNetwork};

/// What FreeSpaceDistanceObjectRoadLane leaves in its PositionDiff.
#[derive(Debug, Clone, Copy)]
pub(crate) struct FreeSpaceGap {
    /// Gap along s in the first entity's driving direction.
    pub ds: f64,
    /// Gap across t, as t grows.
    pub dt: f64,
    /// The front right corners located on the road (first entity, second), the last pair
    /// esmini compares, whose lane difference it reports; `None` when the boxes overlap (esmini
    /// then reports a lane difference of 0).
    pub front_right: Option<(LanePosition, LanePosition)>,
}

/// The corners in esmini's order (first quadrant first, counter-clockwise: front left, rear
/// left, rear right, front right) located on `road`. A corner past the road's end is where the
/// road network puts it (XYZ2TrackPos follows the links: on a closed loop it is near s = 0 again,
/// which makes the deltas change sign); `None` where a corner lies on another road (measured
/// along the road path by [`free_space_roads`] and [`free_space_point_roads`]). Each corner's lane is the one
/// esmini snaps a position to (LaneSection::GetClosestLaneIdx with the lane types of the
/// measuring entity's position: `sidewalks` for a pedestrian).
fn road_corners(net: &RoadNetwork, e: &Entity, road: usize, hint_s: f64, sidewalks: bool) -> Option<[LanePosition; 4]> {
    located_corners(net, e, road, hint_s, sidewalks, true, None)
}

/// [`road_corners`], each corner on the road `world_to_lane` puts it on from a start on `road`
/// (`only_road`: `None` where one lies on another road). With `from` (the measuring entity's
/// position, which XYZ2TrackPos starts from) a corner past its road's end into a junction goes
/// on the connecting road XYZ2TrackPos prefers (junction_entry: directly connected from its
/// lane, the straightest), not merely the nearest, and a corner on a road no path reaches from
/// `from` is placed on `from`'s road (connectedOnly).
fn located_corners(
    net: &RoadNetwork,
    e: &Entity,
    road: usize,
    hint_s: f64,
    sidewalks: bool,
    only_road: bool,
    from: Option<&LanePos>,
) -> Option<[LanePosition; 4]> {
    let [fl, fr, rr, rl] = corners(e);
    let mut out = [None; 4];
    for (k, (x, y)) in [fl, rl, rr, fr].into_iter().enumerate() {
        // A copy of the entity's position: its lane is the current one (XYZ2TrackPos).
        let lane_id = e.lane.filter(|l| l.road == road).map_or(0, |l| l.lane_id);
        let mut p = world_to_lane(net, x, y, Some((road, hint_s, lane_id)))?;
        if only_road && p.road != road {
            return None;
        }
        if let Some(f) = from.filter(|_| p.road != road) {
            if let Some(q) = entry_connector(net, f.road, f.lane_id, x, y) {
                p = q;
            } else if p.road != f.road && crate::roads::road_path::path_ends(net, f.road, f.s, f.lane_id, p.road).is_none() {
                // XYZ2TrackPos with connectedOnly skips the roads no path reaches from `from`:
                // the corner stays on `from`'s road (a stand-in for the nearest reachable one)
                p = net.locate_on_road_by(f.road, x, y, f.s, &crate::roads::banking::surface_t)?;
            }
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
        return Some(FreeSpaceGap { ds: 0.0, dt: 0.0, front_right: None });
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
    Some(FreeSpaceGap { ds: min_ds, dt: min_dt, front_right: Some((ca[3], cb[3])) })
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
        return Some(FreeSpaceGap { ds: 0.0, dt: 0.0, front_right: None });
    }
    let hint = a.lane.map_or(0.0, |l| l.s);
    let sidewalks = a.kind == EntityKind::Pedestrian;
    let ca = located_corners(net, a, road, hint, sidewalks, false, a.lane.as_ref())?;
    let cb = located_corners(net, b, road, b.lane.map_or(hint, |l| l.s), sidewalks, false, a.lane.as_ref())?;
    let backwards = faces_back(net, a);
    gap_of(&ca, &cb, |pa, pb| corner_delta(net, a.h, backwards, pa, pb))
}

/// Whether `a` faces against its road (its heading relative to the road in (pi/2, 3pi/2)).
fn faces_back(net: &RoadNetwork, a: &Entity) -> bool {
    let Some(lp) = a.lane else { return false };
    let Some(road) = net.roads.get(lp.road) else { return false };
    (a.h - crate::roads::pose_memo::reference_pose(road, lp.s.clamp(0.0, road.length)).hdg).cos() < 0.0
}

/// Position::Delta from corner `pa` to `pb` of an entity heading `h`. The corner positions are
/// copies of the entity's that XYZ2TrackPos moved without touching their orientation: they keep
/// its heading and its heading relative to its own road, so `backwards` (that relative heading
/// in (pi/2, 3pi/2), RoadPath::Calculate's test) is the entity's, whatever road the corner lies
/// on. On one road the s difference, turned where `backwards`; across roads the length of the
/// road path between them (RoadPath::Calculate in both directions), negative when the path
/// leaves `pa`'s road behind it, turned again for a heading against `pa`'s lane's driving
/// direction. Across: the t difference, or the sum where the path turns the lane ids around.
/// `None` where no path joins the roads.
fn corner_delta(net: &RoadNetwork, h: f64, backwards: bool, pa: &LanePosition, pb: &LanePosition) -> Option<(f64, f64)> {
    if pa.road == pb.road {
        return Some(((pb.s - pa.s) * if backwards { -1.0 } else { 1.0 }, pb.t - pa.t));
    }
    let ra = net.roads.get(pa.road)?;
    let rb = net.roads.get(pb.road)?;
    let path = crate::roads::road_path::path_ends(net, pa.road, pa.s, pa.lane_id, pb.road)?;
    // RoadPath::Calculate's direction_: +1 when the path leaves by the end the corner faces
    let ahead = (path.first_exit == opendrive::ContactPoint::End) != backwards;
    let mut dist = path.length_to(pb.s, rb.length) * if ahead { 1.0 } else { -1.0 };
    // GetHRelativeDrivingDirection in (pi/2, 3pi/2) as an angle difference in [-pi, pi]
    let drive_h = opendrive::driving_direction::driving_heading(ra.rule, pa.lane_id, pa.heading);
    if crate::angles::angle_difference(h, drive_h) > std::f64::consts::FRAC_PI_2 {
        dist = -dist;
    }
    Some((dist, if path.dt_flips(net, pb.road, pb.s, pa.lane_id) { pb.t + pa.t } else { pb.t - pa.t }))
}

/// Gaps from `a`'s box to the point at (`s`, `t`) on road `road`, `a` facing along s when `dir`
/// is +1: esmini's Object::FreeSpaceDistancePointRoadLane. Each corner's delta to the point
/// (Position::Delta on one road); the gap is the delta smallest in magnitude (the first corner
/// wins ties), and zero only where it and the delta largest in magnitude differ in sign (the
/// other corners are not looked at). `None` where a corner lies off `road`.
pub(crate) fn free_space_point_road(net: &RoadNetwork, a: &Entity, s: f64, t: f64, road: usize, dir: f64) -> Option<(f64, f64)> {
    let hint = a.lane.map_or(s, |l| l.s);
    let ca = road_corners(net, a, road, hint, a.kind == EntityKind::Pedestrian)?;
    Some(point_gap(ca.map(|c| ((s - c.s) * dir, t - c.t))))
}

/// The corners' deltas to a point reduced as FreeSpaceDistancePointRoadLane does, along s and
/// across t apart: the delta smallest in magnitude (the first corner wins ties), zero where it
/// and the delta largest in magnitude differ in sign.
fn point_gap(deltas: [(f64, f64); 4]) -> (f64, f64) {
    let (mut min_ds, mut max_ds, mut min_dt, mut max_dt) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (j, &(ds, dt)) in deltas.iter().enumerate() {
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
    (gap(min_ds, max_ds), gap(min_dt, max_dt))
}

/// [`free_space_point_road`] where the corners or the point may lie on other roads than `a`'s
/// (`road`), as FreeSpaceDistancePointRoadLane has it: each corner is located from `a`'s position
/// (XYZ2TrackPos, the roads connected to it), the point from it too (any road), and each corner's
/// delta to the point is Position::Delta's (along the road path between them). `None` where a
/// corner is on no road or no path joins a corner's road and the point's (esmini: not measured).
pub(crate) fn free_space_point_roads(net: &RoadNetwork, a: &Entity, point: &LanePosition, road: usize) -> Option<(f64, f64)> {
    let hint = a.lane.map_or(point.s, |l| l.s);
    let ca = located_corners(net, a, road, hint, a.kind == EntityKind::Pedestrian, false, a.lane.as_ref())?;
    let backwards = faces_back(net, a);
    let mut deltas = [(0.0, 0.0); 4];
    for (d, c) in deltas.iter_mut().zip(&ca) {
        *d = corner_delta(net, a.h, backwards, c, point)?;
    }
    Some(point_gap(deltas))
}

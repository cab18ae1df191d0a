//! TrajectoryPosition: a point at arc length s along a trajectory, t metres to its left,
//! facing along the trajectory (turned by a relative orientation, replaced by an absolute one).
//! The trajectory's own positions are resolved from the run's current state; a clothoid
//! without a start position starts at the world origin heading east.

use crate::entities::Entity;
use crate::positions::{resolve, Placement, PositionError};
use opendrive::RoadNetwork;
use openscenario::{Orientation, ReferenceContext, Trajectory};
use trajectory::{Interpolation, Path, Pose};

pub(crate) fn trajectory_placement(
    traj: &Trajectory,
    s: f64,
    t: Option<f64>,
    orientation: Option<&Orientation>,
    net: Option<&RoadNetwork>,
    entities: &[Entity],
) -> Result<Placement, PositionError> {
    let resolver = |p: &openscenario::Position| vertex_pose(p, net, entities);
    // esmini's OSCPositionTrajectory evaluates the shape as read: a polyline's heading is not
    // interpolated (PolyLineBase's default INTERPOLATE_NONE; only FollowTrajectoryAction::Start
    // sets a mode), so each segment faces as the vertex it starts at.
    let build = || {
        let place = |p: Pose| placed_pose(net, p);
        let mut p = Path::from_trajectory_placed(traj, Pose::default(), &resolver, &place).map_err(|e| e.to_string())?;
        p.set_interpolation(Interpolation::None);
        Ok(p)
    };
    let path = crate::position_cache::path(traj, build);
    let path = path.map_err(|e| format!("trajectory `{}`: {e}", traj.name))?;
    let p = path.pose_at(s);
    let (x, y) = p.offset(t.unwrap_or(0.0));
    let h = match orientation {
        Some(Orientation { reference: Some(ReferenceContext::Absolute), h: Some(h), .. }) => *h,
        Some(Orientation { h: Some(h), .. }) => p.heading + h,
        _ => p.heading,
    };
    Ok(Placement { x, y, z: None, h, lane: None, world_left: false, h_rel: None })
}

/// The world pose of a position resolved for a trajectory's vertex or control point. A world
/// position without a heading faces the road's reference direction where it lies, plus the
/// lane's drift (esmini's OSCPositionWorld sets such a heading relative to the road, at 0:
/// Position::SetInertiaPosMode, EvaluateHPR); off the roads, 0. On a sloped or banked road
/// a world position's heading is the one esmini's position holds there, the road's rotation
/// composed with the turn from it (`attitude::on_road`, a fresh position; level beyond the
/// road's end).
pub(crate) fn vertex_pose(pos: &openscenario::Position, net: Option<&RoadNetwork>, entities: &[Entity]) -> Option<Pose> {
    let p = resolve(pos, net, entities).ok()?;
    let h = match (pos, net) {
        (openscenario::Position::World { h, .. }, Some(net)) => held_heading(net, p.x, p.y, h.map(|_| p.h)).unwrap_or(p.h),
        _ => p.h,
    };
    Some(Pose::new(p.x, p.y, p.z.unwrap_or(0.0), h))
}

/// A resolved world pose placed as esmini's Position::SetInertiaPos places it: the same point,
/// its heading composed with the road's where it lies ([`held_heading`]). For a ClothoidSpline
/// segment chained to the previous one's end (ClothoidSplineShape::Freeze).
pub(crate) fn placed_pose(net: Option<&RoadNetwork>, p: Pose) -> Pose {
    match net.and_then(|net| held_heading(net, p.x, p.y, Some(p.heading))) {
        Some(h) => Pose { heading: h, ..p },
        None => p,
    }
}

/// The heading esmini's position holds at world point (x, y) given heading `h` (None: the
/// road's reference direction plus the lane's drift): composed with a sloped or banked road's
/// rotation there (`attitude::on_road`, a fresh position; level beyond the road's end). None
/// off the roads.
pub(crate) fn held_heading(net: &RoadNetwork, x: f64, y: f64, h: Option<f64>) -> Option<f64> {
    let lp = crate::roads::locate::world_to_lane(net, x, y, None)?;
    let past_end = crate::roads::past_end::past_road_end(net, lp.road, lp.s, x, y);
    // Without a heading of its own the position keeps a fresh one's absolute 0 when it lies
    // beyond the road's end (XYZ2TrackPos: closestPointInside false, EvaluateHPR with h_ = 0),
    // else it faces the road's reference direction.
    let h = match h {
        Some(h) => h,
        None if strictly_past_end(net, lp.road, lp.s, x, y) => {
            crate::entities::esmini_euler_heading(lp.heading, crate::angles::angle_difference(0.0, lp.heading))
        }
        None => lp.heading + crate::positions::lane_drift(net, lp.road, lp.lane_id, lp.s),
    };
    let road = net.roads.get(lp.road).filter(|_| !past_end);
    let tilted = road.and_then(|r| crate::attitude::on_road(r, lp.s, lp.t, crate::angles::wrap(h - lp.heading), 0.0));
    Some(tilted.map_or(h, |o| o[0]))
}

/// (x, y) projects beyond the start or the end of `road` by any amount (XYZ2TrackPos: the closest
/// lane-0 OSI point is the first or last one and the point lies outward of its normal, by the
/// cross product's sign, no tolerance: closestPointInside false).
fn strictly_past_end(net: &RoadNetwork, road: usize, s: f64, x: f64, y: f64) -> bool {
    let Some(r) = net.roads.get(road) else { return false };
    let (s, _, along) = opendrive::projection::project_onto_road(r, x, y, s);
    // The last OSI point is at L - SMALL_NUMBER/2 (5e-7): a point beyond it, the road's very
    // end included, is outside too.
    let last_osi = r.length - 0.5 * crate::dynamics::ESMINI_SMALL_NUMBER;
    (s + along > last_osi && s >= last_osi) || (s <= 0.0 && along < 0.0)
}

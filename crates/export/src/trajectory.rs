//! A dynamic obstacle's states as a `FollowTrajectoryAction`: a polyline with a vertex per
//! state (time, x, y, heading), absolute timing (`Timing domainAbsoluteRelative="absolute"
//! scale="1" offset="0"`), following mode `position`. A simulator places the entity at the
//! polyline's point for the simulation time, so at every CommonRoad time step it is exactly at
//! that step's state (esmini: `FollowTrajectoryAction::Move` takes the time at the end of the
//! step and interpolates the vertices linearly in time, so a step that lands on a CommonRoad
//! time lands on the vertex).

use commonroad::State;

use crate::entity::BoxShape;
use crate::options::OscVersion;
use crate::xml::{time, El};

/// Where the entity's reference point (its box centre) is for a state: the state's position,
/// moved by the box centre's offset for a polygon.
pub(crate) fn reference(s: &State, shape: &BoxShape) -> (f64, f64) {
    let (sin, cos) = s.orientation.sin_cos();
    (s.x + cos * shape.cx - sin * shape.cy, s.y + sin * shape.cx + cos * shape.cy)
}

/// The `PrivateAction` following `states` (at least two, in time order) at `dt` seconds a step.
pub(crate) fn follow(name: &str, states: &[State], shape: &BoxShape, dt: f64, version: OscVersion) -> El {
    let vertices = states.iter().map(|s| {
        let (x, y) = reference(s, shape);
        El::new("Vertex").attr("time", time(s.time_step as f64 * dt)).child(crate::actions::world(x, y, s.orientation))
    });
    let trajectory = El::new("Trajectory")
        .attr("name", format!("{name}_trajectory"))
        .attr("closed", "false")
        .child(El::new("Shape").child(El::new("Polyline").children(vertices)));
    let timing = El::new("TimeReference").child(El::new("Timing").attr("domainAbsoluteRelative", "absolute").num("scale", 1.0).num("offset", 0.0));
    let mode = El::new("TrajectoryFollowingMode").attr("followingMode", "position");
    let follow = match version {
        // 1.0: the trajectory is a child of the action (wrapped in TrajectoryRef from 1.1 on)
        OscVersion::V1_0 => El::new("FollowTrajectoryAction").child(trajectory).child(timing).child(mode),
        OscVersion::V1_3 => El::new("FollowTrajectoryAction").child(El::new("TrajectoryRef").child(trajectory)).child(timing).child(mode),
    };
    El::new("PrivateAction").child(El::new("RoutingAction").child(follow))
}

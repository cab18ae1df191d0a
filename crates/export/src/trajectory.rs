//! A dynamic obstacle's states as a `FollowTrajectoryAction`: a polyline with a vertex per
//! state (time, x, y, heading), absolute timing (`Timing domainAbsoluteRelative="absolute"
//! scale="1" offset="0"`), following mode `position`. A simulator places the entity at the
//! polyline's point for the simulation time, so at every CommonRoad time step it is exactly at
//! that step's state (esmini: `FollowTrajectoryAction::Move` takes the time at the end of the
//! step and interpolates the vertices linearly in time, so a step that lands on a CommonRoad
//! time lands on the vertex).
//!
//! esmini (and osc2cr's engine, which does as esmini does) thins a polyline's close vertices
//! when the action starts ([`crate::traj_filter`]): where that would move the entity off a
//! state, the states are cut into pieces, a `FollowTrajectoryAction` each, which the filter
//! leaves whole enough; the first piece starts as the single trajectory did, each next one when
//! the simulation time reaches its first state (the previous piece's last), so that in the step
//! after the previous one ended it already moves the entity.

use commonroad::State;

use crate::entity::BoxShape;
use crate::options::OscVersion;
use crate::traj_filter::{pieces, Vertex};
use crate::xml::{time, El};

/// Where the entity's reference point (its box centre) is for a state: the state's position,
/// moved by the box centre's offset for a polygon.
pub(crate) fn reference(s: &State, shape: &BoxShape) -> (f64, f64) {
    let (sin, cos) = s.orientation.sin_cos();
    (s.x + cos * shape.cx - sin * shape.cy, s.y + sin * shape.cx + cos * shape.cy)
}

/// A piece of a trajectory: the time step of its first state and the `PrivateAction`
/// following it.
pub(crate) struct Piece {
    pub first_step: u64,
    pub action: El,
}

/// The `PrivateAction`s following `states` (at least two, in time order) at `dt` seconds a
/// step, piece by piece; the first piece's trajectory is `<name>_trajectory`, the k-th's
/// `<name>_trajectory_<k>`.
pub(crate) fn follow(name: &str, states: &[State], shape: &BoxShape, dt: f64, version: OscVersion) -> Vec<Piece> {
    // each vertex as the simulator reads it: the time as written, the position (written exactly)
    let written: Vec<(String, f64, f64)> = states
        .iter()
        .map(|s| {
            let (x, y) = reference(s, shape);
            (time(s.time_step as f64 * dt), x, y)
        })
        .collect();
    let vertices: Vec<Vertex> =
        written.iter().zip(states).map(|((t, x, y), s)| Vertex { t: t.parse().unwrap_or(s.time_step as f64 * dt), x: *x, y: *y, h: s.orientation }).collect();
    pieces(&vertices)
        .into_iter()
        .enumerate()
        .map(|(k, (a, b))| {
            let trajectory_name = if k == 0 { format!("{name}_trajectory") } else { format!("{name}_trajectory_{}", k + 1) };
            let vertices = (a..=b)
                .map(|i| El::new("Vertex").attr("time", written[i].0.clone()).child(crate::actions::world(written[i].1, written[i].2, states[i].orientation)));
            Piece { first_step: states[a].time_step, action: follow_polyline(trajectory_name, vertices, version) }
        })
        .collect()
}

/// The `PrivateAction` following the polyline of `vertices` with absolute timing.
fn follow_polyline(name: String, vertices: impl Iterator<Item = El>, version: OscVersion) -> El {
    let trajectory = El::new("Trajectory").attr("name", name).attr("closed", "false").child(El::new("Shape").child(El::new("Polyline").children(vertices)));
    let timing = El::new("TimeReference").child(El::new("Timing").attr("domainAbsoluteRelative", "absolute").num("scale", 1.0).num("offset", 0.0));
    let mode = El::new("TrajectoryFollowingMode").attr("followingMode", "position");
    let follow = match version {
        // 1.0: the trajectory is a child of the action (wrapped in TrajectoryRef from 1.1 on)
        OscVersion::V1_0 => El::new("FollowTrajectoryAction").child(trajectory).child(timing).child(mode),
        OscVersion::V1_3 => El::new("FollowTrajectoryAction").child(El::new("TrajectoryRef").child(trajectory)).child(timing).child(mode),
    };
    El::new("PrivateAction").child(El::new("RoutingAction").child(follow))
}

//! Paths from the OpenSCENARIO model: positions resolved through the engine's closure.

use crate::constructors::{PolylineVertex, SplineSegment};
use crate::error::Error;
use crate::path::Path;
use crate::pose::Pose;
use openscenario::model::{Position, Shape, Trajectory};

/// The engine's position resolver: world pose of a position, None if it cannot be placed.
pub type Resolver<'a> = &'a dyn Fn(&Position) -> Option<Pose>;

/// The engine's placement of an already resolved world pose: the pose esmini's position holds
/// there (SetInertiaPos), whose heading is composed with the road's pitch and roll.
pub type Placer<'a> = &'a dyn Fn(Pose) -> Pose;

fn resolve(shape: &'static str, what: String, resolver: Resolver, p: &Position) -> Result<Pose, Error> {
    resolver(p).ok_or(Error::Unresolved { shape, what })
}

impl Path {
    /// [`Path::from_shape`] with the trajectory's own `closed` flag.
    pub fn from_trajectory(trajectory: &Trajectory, current: Pose, resolver: Resolver) -> Result<Path, Error> {
        Path::from_shape(&trajectory.shape, trajectory.closed, current, resolver)
    }

    /// [`Path::from_trajectory`] with the engine's `place` for the poses esmini puts in the world
    /// while it builds the shape (a ClothoidSpline segment chained to the previous one's end).
    pub fn from_trajectory_placed(trajectory: &Trajectory, current: Pose, resolver: Resolver, place: Placer) -> Result<Path, Error> {
        Path::from_shape_placed(&trajectory.shape, trajectory.closed, current, resolver, place)
    }

    /// Build the path of a shape. `current` is the entity's pose when the action starts: the
    /// start of a Clothoid without a Position and of a ClothoidSpline whose first segment
    /// has no PositionStart. Positions are resolved in document order.
    pub fn from_shape(shape: &Shape, closed: bool, current: Pose, resolver: Resolver) -> Result<Path, Error> {
        Path::from_shape_placed(shape, closed, current, resolver, &|p| p)
    }

    /// [`Path::from_shape`] with the engine's `place` (see [`Path::from_trajectory_placed`]).
    pub fn from_shape_placed(shape: &Shape, closed: bool, current: Pose, resolver: Resolver, place: Placer) -> Result<Path, Error> {
        match shape {
            Shape::Polyline(vertices) => {
                let mut v = Vec::with_capacity(vertices.len().min(crate::constructors::MAX_ITEMS + 1));
                for (i, vx) in vertices.iter().take(crate::constructors::MAX_ITEMS + 1).enumerate() {
                    let pose = resolve("Polyline", format!("vertex {i}"), resolver, &vx.position)?;
                    v.push(PolylineVertex { pose, time: vx.time, explicit_heading: gives_heading(&vx.position), relative: is_relative(&vx.position) });
                }
                Path::polyline_of(&v, closed)
            }
            Shape::Clothoid { curvature, curvature_prime, length, start_time, stop_time, position } => {
                let start = match position {
                    Some(p) => resolve("Clothoid", "the start".into(), resolver, p)?,
                    None => current,
                };
                Path::clothoid(start, *curvature, *curvature_prime, *length, (*start_time, *stop_time), closed)
            }
            Shape::ClothoidSpline { segments, time_end } => {
                let mut segs = Vec::with_capacity(segments.len().min(crate::constructors::MAX_ITEMS + 1));
                for (i, s) in segments.iter().take(crate::constructors::MAX_ITEMS + 1).enumerate() {
                    let start = match &s.position_start {
                        Some(p) => Some(resolve("ClothoidSpline", format!("the start of segment {i}"), resolver, p)?),
                        None => None,
                    };
                    segs.push(SplineSegment {
                        start,
                        curvature_start: s.curvature_start,
                        curvature_end: s.curvature_end,
                        length: s.length,
                        h_offset: s.h_offset.unwrap_or(0.0),
                        time_start: s.time_start,
                    });
                }
                Path::clothoid_spline_placed(current, &segs, *time_end, closed, place)
            }
            Shape::Nurbs { order, control_points, knots } => {
                let mut cps = Vec::with_capacity(control_points.len().min(crate::constructors::MAX_ITEMS + 1));
                for (i, c) in control_points.iter().take(crate::constructors::MAX_ITEMS + 1).enumerate() {
                    cps.push((resolve("NURBS", format!("control point {i}"), resolver, &c.position)?, c.weight, c.time));
                }
                let first_gives_heading = control_points.first().is_some_and(|c| gives_heading(&c.position));
                Path::nurbs_with_headings(*order, &cps, knots, closed, first_gives_heading)
            }
        }
    }
}

/// Whether a position gives a heading of its own (esmini sets its heading mode: a World
/// position's h, an Orientation's h).
pub fn gives_heading(p: &Position) -> bool {
    match p {
        Position::World { h, .. } => h.is_some(),
        Position::RelativeWorld { orientation, .. }
        | Position::RelativeObject { orientation, .. }
        | Position::Road { orientation, .. }
        | Position::RelativeRoad { orientation, .. }
        | Position::Lane { orientation, .. }
        | Position::RelativeLane { orientation, .. } => orientation.as_ref().is_some_and(|o| o.h.is_some()),
        _ => false,
    }
}

/// Whether esmini counts a position as relative (not of its NORMAL type): relative to an
/// entity, or in route coordinates.
fn is_relative(p: &Position) -> bool {
    matches!(
        p,
        Position::RelativeWorld { .. }
            | Position::RelativeObject { .. }
            | Position::RelativeRoad { .. }
            | Position::RelativeLane { .. }
            | Position::Route { .. }
    )
}

//! Trajectories (polyline, clothoid, clothoid spline, NURBS) and routes.

use super::{Origin, Position};
use crate::params::ParameterDeclaration;
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trajectory {
    pub name: String,
    pub closed: bool,
    pub parameters: Vec<ParameterDeclaration>,
    pub shape: Shape,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Shape {
    Polyline(Vec<Vertex>),
    /// One clothoid; `position` is its start (None: the entity's current position).
    Clothoid {
        curvature: f64,
        curvature_prime: f64,
        length: f64,
        start_time: Option<f64>,
        stop_time: Option<f64>,
        position: Option<Box<Position>>,
    },
    ClothoidSpline {
        segments: Vec<ClothoidSplineSegment>,
        time_end: Option<f64>,
    },
    Nurbs {
        order: u32,
        control_points: Vec<ControlPoint>,
        knots: Vec<f64>,
    },
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Vertex {
    pub time: Option<f64>,
    pub position: Position,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ClothoidSplineSegment {
    pub curvature_start: f64,
    pub curvature_end: f64,
    pub length: f64,
    pub h_offset: Option<f64>,
    pub time_start: Option<f64>,
    pub position_start: Option<Position>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ControlPoint {
    pub time: Option<f64>,
    pub weight: Option<f64>,
    pub position: Position,
}

crate::xml_enum! {
    RouteStrategy { Fastest = "fastest", Shortest = "shortest", LeastIntersections = "leastIntersections", Random = "random" }
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Route {
    pub name: String,
    pub closed: bool,
    pub parameters: Vec<ParameterDeclaration>,
    pub waypoints: Vec<Waypoint>,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Waypoint {
    pub position: Position,
    pub strategy: RouteStrategy,
}

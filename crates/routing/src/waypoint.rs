//! Route input: waypoints in road coordinates and route strategies.

/// A waypoint resolved by the engine to road coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Waypoint {
    /// Index into `RoadNetwork::roads`.
    pub road: usize,
    pub lane: i32,
    pub s: f64,
    /// Direction of travel through the waypoint: `Some(true)` along +s; `None` means the
    /// lane's driving direction.
    pub along_s: Option<bool>,
}

/// OpenSCENARIO's routeStrategy.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Strategy {
    /// Least distance.
    Shortest,
    /// Least time at the roads' speed limits.
    Fastest,
    /// Fewest junctions entered, then least distance.
    LeastIntersections,
    /// Planned as `Shortest` (deterministic); the route records that it was asked for.
    Random,
}

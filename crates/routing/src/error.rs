//! Why no route could be planned.

use thiserror::Error;

#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum Error {
    #[error("a route needs at least 2 waypoints, found {found}")]
    TooFewWaypoints { found: usize },
    #[error("a route may have at most {max} waypoints, found {found}")]
    TooManyWaypoints { max: usize, found: usize },
    #[error("waypoint {index}: {reason}")]
    BadWaypoint { index: usize, reason: String },
    #[error("no drivable way from waypoint {from} (road `{from_road}`) to waypoint {to} (road `{to_road}`)")]
    NoPath { from: usize, to: usize, from_road: String, to_road: String },
}

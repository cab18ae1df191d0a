//! Obstacles. Each element kind has its own type enum with exactly the values the XSD allows
//! for it, so e.g. a static `car` cannot be built (commonroad-io 2020a has no static car).

use crate::geometry::{AbsoluteShape, Shape};
use crate::ids::ObstacleId;
use crate::str_enum::str_enum;

str_enum!(
    /// Types a `staticObstacle` may have.
    StaticObstacleType {
        Unknown => "unknown",
        ParkedVehicle => "parkedVehicle",
        ConstructionZone => "constructionZone",
        RoadBoundary => "roadBoundary",
    }
);

str_enum!(
    /// Types a `dynamicObstacle` may have.
    DynamicObstacleType {
        Unknown => "unknown",
        Car => "car",
        Truck => "truck",
        Bus => "bus",
        Motorcycle => "motorcycle",
        Bicycle => "bicycle",
        Pedestrian => "pedestrian",
        PriorityVehicle => "priorityVehicle",
        Train => "train",
        Taxi => "taxi",
    }
);

str_enum!(
    /// Types an `environmentObstacle` may have.
    EnvironmentObstacleType {
        Unknown => "unknown",
        Building => "building",
        Pillar => "pillar",
        MedianStrip => "median_strip",
    }
);

/// The state of a dynamic obstacle at one time step. One struct with fixed fields, so every
/// state of a trajectory has the identical field set (the readers assert that).
/// Position is the centre of the obstacle's shape, in metres; angles in rad (CCW from +x,
/// keep orientation in (-π, π]); velocity m/s; acceleration m/s²; yaw rate rad/s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    pub time_step: u64,
    pub x: f64,
    pub y: f64,
    pub orientation: f64,
    pub velocity: f64,
    pub acceleration: f64,
    pub yaw_rate: f64,
}

impl State {
    /// The finite-ness of every field.
    pub fn is_finite(&self) -> bool {
        [self.x, self.y, self.orientation, self.velocity, self.acceleration, self.yaw_rate].iter().all(|v| v.is_finite())
    }
}

/// A `staticObstacle` (written with initial time step 0).
#[derive(Debug, Clone, PartialEq)]
pub struct StaticObstacle {
    pub id: ObstacleId,
    pub obstacle_type: StaticObstacleType,
    pub shape: Shape,
    /// Centre of the shape.
    pub x: f64,
    pub y: f64,
    pub orientation: f64,
}

/// A `dynamicObstacle` with a trajectory.
///
/// `initial_state.time_step` may be > 0 for an obstacle that appears during the run (what
/// commonroad-io writes for dataset scenarios; cr_check warns because the XSD pins it to 0).
/// The trajectory must hold at least one state, with time steps `t0+1, t0+2, …` where
/// `t0 = initial_state.time_step` (`validate()` checks).
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicObstacle {
    pub id: ObstacleId,
    pub obstacle_type: DynamicObstacleType,
    pub shape: Shape,
    pub initial_state: State,
    pub trajectory: Vec<State>,
}

/// An `environmentObstacle` (buildings, pillars, median strips), placed in world coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct EnvironmentObstacle {
    pub id: ObstacleId,
    pub obstacle_type: EnvironmentObstacleType,
    pub shape: AbsoluteShape,
}

//! Planning problems: an exact initial state and goal regions with interval bounds.

use crate::error::{finite, Error};
use crate::geometry::{PlacedCircle, PlacedRectangle, Polygon};
use crate::ids::{LaneletId, PlanningProblemId};

/// The planning problem's initial state. Written with time step 0 and every field the XSD's
/// `initialStateExact` requires (position, velocity, orientation, yaw rate, slip angle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanningInitialState {
    pub x: f64,
    pub y: f64,
    pub orientation: f64,
    pub velocity: f64,
    pub yaw_rate: f64,
    pub slip_angle: f64,
    /// Optional in the XSD.
    pub acceleration: Option<f64>,
}

/// A closed interval `[start, end]` of reals, finite, `start <= end`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    start: f64,
    end: f64,
}

impl Interval {
    pub fn new(start: f64, end: f64) -> Result<Self, Error> {
        finite("interval start", start)?;
        finite("interval end", end)?;
        if start > end {
            return Err(Error::ReversedInterval { start, end });
        }
        Ok(Self { start, end })
    }
    pub fn start(&self) -> f64 {
        self.start
    }
    pub fn end(&self) -> f64 {
        self.end
    }
}

/// A time-step interval `[start, end]` with `start <= end` and `end >= 1` (XSD
/// `integerIntervalGreaterZero`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TimeInterval {
    start: u64,
    end: u64,
}

impl TimeInterval {
    pub fn new(start: u64, end: u64) -> Result<Self, Error> {
        if end == 0 || start > end {
            return Err(Error::BadTimeInterval { start, end });
        }
        Ok(Self { start, end })
    }
    pub fn start(&self) -> u64 {
        self.start
    }
    pub fn end(&self) -> u64 {
        self.end
    }
}

/// A goal position set: the XSD allows one kind of element, repeated.
#[derive(Debug, Clone, PartialEq)]
pub enum GoalPosition {
    Rectangles(Vec<PlacedRectangle>),
    Circles(Vec<PlacedCircle>),
    Polygons(Vec<Polygon>),
    Lanelets(Vec<LaneletId>),
}

/// A `goalState`. Time is required and an interval; the rest optional.
#[derive(Debug, Clone, PartialEq)]
pub struct GoalState {
    pub time: TimeInterval,
    /// Must not be an empty list (`validate()` checks).
    pub position: Option<GoalPosition>,
    pub orientation: Option<Interval>,
    pub velocity: Option<Interval>,
}

impl GoalState {
    /// A goal that only constrains time.
    pub fn at_time(time: TimeInterval) -> Self {
        Self { time, position: None, orientation: None, velocity: None }
    }
}

/// A `planningProblem`.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanningProblem {
    pub id: PlanningProblemId,
    pub initial_state: PlanningInitialState,
    /// At least one (XSD); `validate()` reports an empty list.
    pub goal_states: Vec<GoalState>,
}

/// The planning problems of one file (at least one for a scenario file, none for a map).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PlanningProblemSet {
    pub problems: Vec<PlanningProblem>,
}

//! The ego's planning problem: its first state as the initial state, and a goal around its
//! last state — by default a 50 m × 10 m rectangle centred on the last position and rotated
//! to the last heading, the time steps [T−10, T] (T = the last step), and the last speed ± 5 m/s
//! (never below 0).

use commonroad::{
    GoalPosition, GoalState, Interval, PlacedRectangle, PlanningInitialState, PlanningProblem, PlanningProblemId, Point, Rectangle, State, TimeInterval,
};
use serde::Serialize;

/// Shape of the goal region.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GoalOptions {
    /// Rectangle length along the last heading, m.
    pub length: f64,
    /// Rectangle width, m.
    pub width: f64,
    /// Time steps before the last one that still reach the goal.
    pub time_window: u64,
    /// Half-width of the velocity interval, m/s; `None` leaves the velocity free.
    pub speed_margin: Option<f64>,
    /// Half-width of the orientation interval, rad; `None` (default) leaves it free.
    pub orientation_margin: Option<f64>,
}

impl Default for GoalOptions {
    fn default() -> Self {
        Self { length: 50.0, width: 10.0, time_window: 10, speed_margin: Some(5.0), orientation_margin: None }
    }
}

/// The planning problem of an ego whose first state is `first` and last state `last`.
pub fn planning_problem(id: PlanningProblemId, first: &State, last: &State, options: &GoalOptions) -> Result<PlanningProblem, commonroad::Error> {
    let initial_state = PlanningInitialState {
        x: first.x,
        y: first.y,
        orientation: first.orientation,
        velocity: first.velocity,
        yaw_rate: first.yaw_rate,
        slip_angle: 0.0,
        acceleration: Some(first.acceleration),
    };
    let end = last.time_step.max(1);
    let time = TimeInterval::new(end.saturating_sub(options.time_window), end)?;
    let rectangle =
        PlacedRectangle { rectangle: Rectangle::new(options.length, options.width)?, center: Point::new(last.x, last.y), orientation: last.orientation };
    let velocity = match options.speed_margin {
        Some(m) => Some(Interval::new((last.velocity - m).max(0.0), (last.velocity + m).max(0.0))?),
        None => None,
    };
    let orientation = match options.orientation_margin {
        Some(m) => Some(Interval::new(last.orientation - m, last.orientation + m)?),
        None => None,
    };
    Ok(PlanningProblem {
        id,
        initial_state,
        goal_states: vec![GoalState { time, position: Some(GoalPosition::Rectangles(vec![rectangle])), orientation, velocity }],
    })
}

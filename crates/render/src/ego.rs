//! Which dynamic obstacle is the ego: the one the user names, else the one that starts where
//! the (first) planning problem starts — a converter keeps the ego as an obstacle whose
//! initial state is the planning problem's initial state.

use commonroad::{DynamicObstacle, ObstacleId, PlanningProblemSet, Scenario};

use crate::error::Error;

/// How far (m) the obstacle's initial position may be from the planning problem's (files hold
/// 4–6 decimals, so equal positions differ by far less).
pub const SAME_POSITION_M: f64 = 0.01;

/// The ego's id: `chosen` if given (it must exist), else the obstacle at the planning
/// problem's initial position at time step 0 (nearest first, then smallest id), else none.
pub fn find_ego(scenario: &Scenario, problems: Option<&PlanningProblemSet>, chosen: Option<u64>) -> Result<Option<ObstacleId>, Error> {
    if let Some(id) = chosen {
        return scenario.dynamic_obstacles.iter().find(|o| o.id.get() == id).map(|o| Some(o.id)).ok_or(Error::UnknownEgo(id));
    }
    let Some(start) = problems.and_then(|p| p.problems.first()) else {
        return Ok(None);
    };
    let (px, py) = (start.initial_state.x, start.initial_state.y);
    let distance = |o: &DynamicObstacle| (o.initial_state.x - px).hypot(o.initial_state.y - py);
    Ok(scenario
        .dynamic_obstacles
        .iter()
        .filter(|o| o.initial_state.time_step == 0 && distance(o) <= SAME_POSITION_M)
        .min_by(|a, b| distance(a).total_cmp(&distance(b)).then(a.id.cmp(&b.id)))
        .map(|o| o.id))
}

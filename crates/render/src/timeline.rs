//! Time: which state an obstacle has at a time step, how long the scenario runs, and which
//! colour a traffic light shows.

use commonroad::{DynamicObstacle, Scenario, State, TrafficLight, TrafficLightColor};

/// The time step nearest to `seconds` (time steps are `dt` apart).
pub fn step_of(seconds: f64, dt: f64) -> u64 {
    let s = (seconds / dt).round();
    // saturating: a huge time simply lies after every trajectory
    if s.is_finite() && s > 0.0 {
        if s >= u64::MAX as f64 {
            u64::MAX
        } else {
            s as u64
        }
    } else {
        0
    }
}

/// The obstacle's state at `step`, or `None` when it does not exist then (before its initial
/// state or after its last). Looked up by time step, not by index, so a trajectory with gaps
/// shows the obstacle only where the file says where it is.
pub fn state_at(o: &DynamicObstacle, step: u64) -> Option<&State> {
    if step == o.initial_state.time_step {
        return Some(&o.initial_state);
    }
    let t0 = o.initial_state.time_step;
    let guess = step.checked_sub(t0 + 1).and_then(|i| usize::try_from(i).ok());
    if let Some(s) = guess.and_then(|i| o.trajectory.get(i)) {
        if s.time_step == step {
            return Some(s);
        }
    }
    o.trajectory.iter().find(|s| s.time_step == step)
}

/// The last time step of any dynamic obstacle (0 for a scenario without one).
pub fn last_step(scenario: &Scenario) -> u64 {
    scenario.dynamic_obstacles.iter().flat_map(|o| std::iter::once(&o.initial_state).chain(&o.trajectory)).map(|s| s.time_step).max().unwrap_or(0)
}

/// The first time step of any dynamic obstacle (0 for a scenario without one).
pub fn first_step(scenario: &Scenario) -> u64 {
    scenario.dynamic_obstacles.iter().map(|o| o.initial_state.time_step).min().unwrap_or(0)
}

/// The colour a light shows at `step`: its cycle repeats from `-time_offset`; an inactive
/// light (or one without phases) shows `Inactive`.
pub fn light_color(light: &TrafficLight, step: u64) -> TrafficLightColor {
    if light.active == Some(false) {
        return TrafficLightColor::Inactive;
    }
    let period: u64 = light.cycle.iter().fold(0u64, |a, c| a.saturating_add(c.duration.get()));
    if period == 0 {
        return TrafficLightColor::Inactive;
    }
    let mut t = step.wrapping_add(light.time_offset) % period;
    for c in &light.cycle {
        if t < c.duration.get() {
            return c.color;
        }
        t -= c.duration.get();
    }
    TrafficLightColor::Inactive
}

//! How a LaneChangeAction over time moves the entity in one step, as esmini 3.6.0 does: the
//! step's lateral part is the transition's rate at the start of the step times dt, its
//! longitudinal part what is left of speed × dt, and the heading is the direction of that step
//! (asin(rate / speed), not atan(rate / speed)). Straight fixture road (lane -1 centred on
//! y = -1.75, lane -2 on y = -5.25); hand computations.

use crate::common::*;
use std::f64::consts::PI;

const V: f64 = 10.0;
const SPAN: f64 = 2.0;
const WIDTH: f64 = 3.5;

/// Rate of the sinusoidal offset 3.5 (1 - cos(π p / 2)) / 2 at parameter `p`.
fn rate(p: f64) -> f64 {
    WIDTH * PI / (2.0 * SPAN) * (PI * p / SPAN).sin()
}

fn run_lane_change() -> engine::Run {
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, V));
    let lc = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="2" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let stories = story("Ego", &event("Change", "overwrite", lc, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let stop = stop_at(5.0);
    run_with(&xosc(&init, &stories, &stop), &engine::Settings { step: 0.01, max_time: 5.0 })
}

#[test]
fn heading_is_the_direction_of_the_step_taken_with_the_rate_at_its_start() {
    // The event starts at 1.01; the row at 1.01 + k·0.01 is after k steps (parameter k·0.01),
    // and its step used the rate at (k - 1)·0.01. At k = 101 that is the peak rate
    // 3.5 π / 4 = 2.749 m/s: heading -asin(0.2749) (to the right).
    let run = run_lane_change();
    let start = event_time(&run, "Change", "start").expect("lane change starts");
    assert!(close(start, 1.01, 1e-9), "{start}");
    let peak = rate(1.0);
    let h = at(&run, "Ego", 2.02).h;
    let h = if h > PI { h - 2.0 * PI } else { h };
    assert!(close(h, -(peak / V).asin(), 1e-9), "{h} vs {}", -(peak / V).asin());
    // The first step starts at rate 0: straight ahead, a full 0.1 m forward.
    let (a, b) = (at(&run, "Ego", 1.01), at(&run, "Ego", 1.02));
    assert!(close(b.x - a.x, V * 0.01, 1e-9), "{}", b.x - a.x);
    assert!(close(b.h.sin(), 0.0, 1e-12), "{}", b.h);
}

#[test]
fn forward_travel_is_what_the_lateral_steps_leave_of_the_step_length() {
    // Over the 200 steps x advances Σ sqrt((v·dt)² - (rate((k-1)·dt)·dt)²); the entity ends in
    // lane -2's centre, heading along the road.
    let run = run_lane_change();
    let dt = 0.01;
    let forward: f64 = (1..=200).map(|k| ((V * dt).powi(2) - (rate((k - 1) as f64 * dt) * dt).powi(2)).sqrt()).sum();
    let (a, b) = (at(&run, "Ego", 1.01), at(&run, "Ego", 3.01));
    assert!(close(a.x, 10.0 + V * 1.01, 1e-9), "{}", a.x);
    assert!(close(b.x - a.x, forward, 1e-6), "{} vs {forward}", b.x - a.x);
    assert!(close(b.y, -5.25, 1e-6), "{}", b.y);
    // Half way (k = 100) too, where using the rate at the start of each step matters most.
    let half: f64 = (1..=100).map(|k| ((V * dt).powi(2) - (rate((k - 1) as f64 * dt) * dt).powi(2)).sqrt()).sum();
    assert!(close(at(&run, "Ego", 2.01).x - a.x, half, 1e-6), "{} vs {half}", at(&run, "Ego", 2.01).x - a.x);
    assert!(close(b.h.sin(), 0.0, 1e-12), "{}", b.h);
}

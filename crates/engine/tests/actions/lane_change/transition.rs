//! LaneChangeAction's transition as esmini's TransitionDynamics has it, on the straight fixture
//! road (lanes 3.5 m wide, see `common`): a rate is the peak lateral speed of the shape, and the
//! parameter never runs past its span, so the last step lands on the target offset.

use crate::common::*;

fn lane_change(shape: &str, dim: &str, value: f64, lane: i32, offset: f64) -> String {
    format!(
        r#"<PrivateAction><LateralAction><LaneChangeAction targetLaneOffset="{offset}"><LaneChangeActionDynamics dynamicsShape="{shape}" value="{value}" dynamicsDimension="{dim}"/><LaneChangeTarget><AbsoluteTargetLane value="{lane}"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#
    )
}

fn run_change(action: &str, stop: f64) -> engine::Run {
    // One Private element per entity: esmini refuses a second one for the same entity.
    let init = format!("{}{}", placed_in_one_private("Ego", 10.0, -1, 10.0), teleport("Target", 500.0, 1));
    let stories = story("Ego", &event("LC", "overwrite", action, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let stop = stop_at(stop);
    run(&xosc(&init, &stories, &stop))
}

#[test]
fn a_sinusoidal_rate_is_the_peak_lateral_speed() {
    // 3.5 m at a peak of 1 m/s on a sinusoid takes π · 3.5 / 2 = 5.4978 s (not 3.5 s, the time
    // at a constant 1 m/s): from 1.01 the parameter reaches its span in the 550th step.
    let run = run_change(&lane_change("sinusoidal", "rate", 1.0, -2, 0.0), 8.0);
    let end = event_time(&run, "LCAction", "end").expect("the lane change ends");
    assert!(close(end, 1.01 + 5.49, 1e-9), "ends at {end}");
    // Halfway in time it is halfway across: lane -1's centre is y = -1.75, lane -2's -5.25.
    assert!(close(at(&run, "Ego", 1.01 + 5.4978 / 2.0).y, -3.5, 0.01), "{:?}", at(&run, "Ego", 3.76));
    // esmini 3.6.0 on this scenario (run by hand): ends at 6.50; (47.531343, -3.501106) at
    // t = 3.76 and x = 79.862297 at t = 7.
    let (e, f) = (at(&run, "Ego", 3.76), at(&run, "Ego", 7.0));
    assert!(close(e.x, 47.531343, 1e-5) && close(e.y, -3.501106, 1e-5) && close(f.x, 79.862297, 1e-5), "{e:?} {f:?}");
}

#[test]
fn a_lane_change_over_distance_ends_exactly_on_the_target_offset() {
    // Linear over 25 m at 10 m/s: the parameter is clamped at 25 m in the last step, so the
    // entity ends 0.3 m left of lane -2's centre, y = -5.25 + 0.3, not past it.
    let run = run_change(&lane_change("linear", "distance", 25.0, -2, 0.3), 6.0);
    let e = at(&run, "Ego", 5.0);
    assert!(close(e.y, -4.95, 1e-9), "{e:?}");
    // esmini 3.6.0 on this scenario (run by hand): ends at 3.53, x = 59.795255 at t = 5.
    assert!(close(event_time(&run, "LCAction", "end").unwrap_or(0.0), 3.53, 1e-9));
    assert!(close(e.x, 59.795255, 1e-5), "{e:?}");
}

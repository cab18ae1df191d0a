//! Whole-run properties: the time cap, determinism, no panic on odd settings.

use crate::common::*;
use engine::Settings;

#[test]
fn max_time_caps_a_run_without_stop_trigger() {
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let run = run_with(&xosc(&init, "", ""), &Settings { step: 0.01, max_time: 3.0 });
    assert_eq!(run.trace.len, 301);
    assert!(close(run.trace.duration(), 3.0, 1e-9));
    assert!(close(at(&run, "Ego", 3.0).x, 40.0, 1e-9));
}

#[test]
fn two_runs_are_identical() {
    let lc = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="cubic" value="20" dynamicsDimension="distance"/><LaneChangeTarget><RelativeTargetLane entityRef="Ego" value="-1"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "sinusoidal", "time", 3.0, 15.0));
    let text = xosc(&init, &story("Ego", &event("LC", "overwrite", lc, &trigger(&sim_time(1.0, "greaterThan", "rising", 0.0)))), "");
    let a = run_with(&text, &Settings { step: 0.01, max_time: 8.0 });
    let b = run_with(&text, &Settings { step: 0.01, max_time: 8.0 });
    assert_eq!(a, b);
    assert_eq!(a.trace.to_csv(&[]), b.trace.to_csv(&[]));
    // The relative lane change to the right ends in lane -2.
    assert_eq!(at(&a, "Ego", 8.0).road.map(|r| r.lane_id), Some(-2));
}

#[test]
fn bad_settings_are_errors() {
    let text = xosc(&teleport("Ego", 10.0, -1), "", "");
    let sc = scenario_of(&text);
    for s in [Settings { step: 0.0, max_time: 1.0 }, Settings { step: 0.01, max_time: f64::NAN }, Settings { step: 1e-9, max_time: 1e9 }] {
        assert!(engine::simulate(&sc, None, &s).is_err());
    }
    // Without a road network a lane position is a warning, not a panic.
    let run = engine::simulate(&sc, None, &Settings { step: 0.01, max_time: 0.5 }).expect("runs");
    assert!(run.warnings.iter().any(|w| w.message.contains("road network")));
}

#[test]
fn a_passed_deadline_stops_the_run_at_the_next_clock_check() {
    let text = xosc(&teleport("Ego", 10.0, -1), "", "");
    let sc = scenario_of(&text);
    let settings = Settings { step: 0.01, max_time: 60.0 };
    // The clock is looked at every 256 steps: the first look is in step 256, whose frame
    // starts at 255 × 0.01 s.
    let control = engine::RunControl { seed: 0, deadline: Some(std::time::Instant::now()) };
    match engine::simulate_with(&sc, None, &settings, &control) {
        Err(engine::Error::Deadline(t)) => assert!(close(t, 2.55, 1e-9), "{t}"),
        other => panic!("expected a deadline error, got {other:?}"),
    }
    // Without a deadline the same run goes to the cap.
    let run = engine::simulate_with(&sc, None, &settings, &engine::RunControl::default()).expect("runs");
    assert_eq!(run.trace.len, 6001);
}

//! Each action on purpose-built scenarios on the straight fixture road, checked against hand
//! computations (see `common` for the road and the cars).

use crate::common::*;

#[test]
fn teleport_places_on_lane_centre_facing_driving_direction() {
    let init = format!("{}{}", teleport("Ego", 10.0, -1), teleport("Target", 50.0, 1));
    let run = run(&xosc(&init, "", &stop_at(1.0)));
    let e = at(&run, "Ego", 0.0);
    assert!(close(e.x, 10.0, 1e-9) && close(e.y, -1.75, 1e-9) && close(e.h, 0.0, 1e-9));
    // Lane 1 is left of the reference line and drives against s: heading π.
    let t = at(&run, "Target", 0.0);
    assert!(close(t.x, 50.0, 1e-9) && close(t.y, 1.75, 1e-9) && close(t.h, std::f64::consts::PI, 1e-9));
}

#[test]
fn step_speed_moves_speed_times_time() {
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let run = run(&xosc(&init, "", &stop_at(5.0)));
    // Speed applies from the first step: x = 10 + 10 t.
    assert!(close(at(&run, "Ego", 1.0).x, 20.0, 1e-9));
    assert!(close(at(&run, "Ego", 3.0).x, 40.0, 1e-9));
    // Lane 1 target speed 0: the Target has no init and stays at the origin, off no lane needed.
    // The storyboard stop trigger (t > 5) fires at 5.01: the last row is at 5.01.
    assert!(close(run.trace.duration(), 5.01, 1e-9));
}

#[test]
fn linear_rate_speed_reaches_target_on_time() {
    // 0 -> 10 m/s at 5 m/s²: the j-th step sets 0.05 j m/s, reached at j = 200 (t = 2 s).
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "linear", "rate", 5.0, 10.0));
    let run = run(&xosc(&init, "", &stop_at(5.0)));
    assert!(close(at(&run, "Ego", 2.0).speed, 10.0, 1e-9));
    assert!(close(at(&run, "Ego", 1.0).speed, 5.0, 1e-9));
    // Distance after 200 steps: 0.01 · Σ 0.05 j = 0.0005 · 200 · 201 / 2 = 10.05 m.
    assert!(close(at(&run, "Ego", 2.0).x, 20.05, 1e-9));
    assert!(close(at(&run, "Ego", 3.0).x, 30.05, 1e-9));
}

#[test]
fn shapes_over_time_and_distance() {
    for (shape, dim, value) in [("linear", "time", 2.0), ("cubic", "time", 2.0), ("sinusoidal", "time", 2.0), ("linear", "distance", 10.0)] {
        // 0 -> 10 m/s over 2 s, or over 10 m (= 2 s at a mean speed of 5 m/s). Every shape is
        // symmetric about its midpoint, so the speed at 1 s is 5 m/s.
        let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", shape, dim, value, 10.0));
        let run = run(&xosc(&init, "", &stop_at(4.0)));
        assert!(close(at(&run, "Ego", 1.0).speed, 5.0, 1e-6), "{shape} {dim}: {}", at(&run, "Ego", 1.0).speed);
        assert!(close(at(&run, "Ego", 2.5).speed, 10.0, 1e-9), "{shape} {dim}");
        // About 10 m covered during the transition (the discrete sum differs by one step).
        let d = at(&run, "Ego", 2.0).x - 10.0;
        assert!((d - 10.0).abs() < 0.11, "{shape} {dim}: {d}");
    }
}

#[test]
fn relative_continuous_speed_tracks_the_reference() {
    let init = format!(
        "{}{}{}{}",
        teleport("Ego", 10.0, -1),
        teleport("Target", 10.0, -2),
        init_speed("Ego", "step", "time", 0.0, 10.0),
        r#"<Private entityRef="Target"><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><RelativeTargetSpeed entityRef="Ego" value="2" speedTargetValueType="delta" continuous="true"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>"#
    );
    let run = run(&xosc(&init, "", &stop_at(3.0)));
    assert!(close(at(&run, "Target", 2.0).speed, 12.0, 1e-9));
    // The continuous action never ends.
    assert!(event_time(&run, "Init Target SpeedAction", "end").is_none());
}

#[test]
fn lane_change_ends_in_the_target_lane() {
    let lc = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="2" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let stories = story("Ego", &event("LC", "overwrite", lc, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let run = run(&xosc(&init, &stories, &stop_at(6.0)));
    // Starts at 1.01 (1.00 is not > 1), takes 2 s of parameter: ends at 3.00.
    assert!(close(event_time(&run, "LC", "start").unwrap_or(-1.0), 1.01, 1e-9));
    let end = event_time(&run, "LCAction", "end").unwrap_or(-1.0);
    assert!(close(end, 3.0, 0.011), "{end}");
    // Halfway (2.01) the sinusoid is at half the 3.5 m: y = -1.75 - 1.75.
    let mid = at(&run, "Ego", 2.01);
    assert!(close(mid.y, -3.5, 0.02), "{}", mid.y);
    assert!(mid.h < 0.0 || mid.h > 6.0, "turning right while changing to the right lane");
    let after = at(&run, "Ego", 4.0);
    assert!(close(after.y, -5.25, 1e-9) && close(after.h, 0.0, 1e-9));
    assert_eq!(after.road.map(|r| r.lane_id), Some(-2));
    // The path is longer than the straight line: less than 10 m/s forward while moving sideways.
    assert!(after.x < 10.0 + 40.0);
}

#[test]
fn lane_offset_reaches_its_target() {
    // Cubic 0 -> 1 m with max lateral acceleration 2 m/s²: span sqrt(6 · 1 / 2) = 1.732 s.
    let lo = r#"<PrivateAction><LateralAction><LaneOffsetAction continuous="false"><LaneOffsetActionDynamics maxLateralAcc="2" dynamicsShape="cubic"/><LaneOffsetTarget><AbsoluteTargetLaneOffset value="1.0"/></LaneOffsetTarget></LaneOffsetAction></LateralAction></PrivateAction>"#;
    let init = format!("{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let stories = story("Ego", &event("LO", "overwrite", lo, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let run = run(&xosc(&init, &stories, &stop_at(5.0)));
    let end = event_time(&run, "LOAction", "end").unwrap_or(-1.0);
    assert!(close(end, 1.01 + 3f64.sqrt(), 0.011), "{end}");
    assert!(close(at(&run, "Ego", 4.0).y, -0.75, 1e-9));
    // Longitudinal motion is unaffected: x = 10 + 10 t.
    assert!(close(at(&run, "Ego", 4.0).x, 50.0, 1e-9));
}

#[test]
fn parameter_set_is_seen_by_parameter_condition() {
    let set = r#"<GlobalAction><ParameterAction parameterRef="X"><SetAction value="5"/></ParameterAction></GlobalAction>"#;
    let cond = r#"<Condition name="p" delay="0" conditionEdge="none"><ByValueCondition><ParameterCondition parameterRef="X" value="5" rule="equalTo"/></ByValueCondition></Condition>"#;
    let events = format!(
        "{}{}",
        event("Set", "parallel", set, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))),
        event("Go", "parallel", &speed_action("step", "time", 0.0, 7.0), &trigger(cond))
    );
    let init = teleport("Ego", 10.0, -1);
    let run = run(&xosc(&init, &story("Ego", &events), &stop_at(3.0)));
    let t = event_time(&run, "Go", "start").unwrap_or(-1.0);
    assert!((1.01..=1.02 + 1e-9).contains(&t), "{t}");
    assert!(close(at(&run, "Ego", 2.5).speed, 7.0, 1e-9));
}

#[test]
fn visibility_is_recorded() {
    let vis = r#"<PrivateAction><VisibilityAction graphics="false" traffic="false" sensors="false"/></PrivateAction>"#;
    // Target is placed too: an entity the Init does not name does not exist (esmini).
    let init = format!("{}{}<Private entityRef=\"Ego\">{vis}</Private>", teleport("Ego", 10.0, -1), teleport("Target", 30.0, -1));
    let run = run(&xosc(&init, "", &stop_at(1.0)));
    assert!(!at(&run, "Ego", 0.5).visible);
    assert!(at(&run, "Target", 0.5).visible);
}

#[test]
fn unsupported_action_is_a_positioned_warning() {
    let traj = r#"<PrivateAction><RoutingAction><RandomRouteAction/></RoutingAction></PrivateAction>"#.to_string();
    let init = format!("{}<Private entityRef=\"Ego\">{traj}</Private>", teleport("Ego", 10.0, -1));
    let run = run(&xosc(&init, "", &stop_at(1.0)));
    let w = run.warnings.iter().find(|w| w.message.contains("RandomRouteAction")).expect("warning");
    assert!(w.location.line > 0 && w.location.col > 0);
}

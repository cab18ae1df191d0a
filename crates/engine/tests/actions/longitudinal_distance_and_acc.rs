//! LongitudinalDistanceAction and the ACC controller on the straight fixture road, against hand
//! computations (see `common`: cars 4.5 m long, box centre 1.5 m ahead of the reference point,
//! maximum acceleration and deceleration 200 m/s²).

use crate::common::*;

fn long_distance(attrs: &str, constraints: &str) -> String {
    format!(
        r#"<PrivateAction><LongitudinalAction><LongitudinalDistanceAction entityRef="Target" {attrs}>{constraints}</LongitudinalDistanceAction></LongitudinalAction></PrivateAction>"#
    )
}

fn scenario(action: &str) -> String {
    scenario_from(action, 10.0, 20.0)
}

fn scenario_from(action: &str, ego_s: f64, ego_speed: f64) -> String {
    // Target at s = 100 drives 10 m/s; Ego at `ego_s` drives `ego_speed`, same lane.
    let init = format!("{}{}", placed("Ego", ego_s, -1, ego_speed), placed("Target", 100.0, -1, 10.0));
    let stories = story("Ego", &event("Keep", "overwrite", action, &trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))));
    xosc(&init, &stories, &stop_at(15.0))
}

#[test]
fn unconstrained_distance_is_kept_exactly() {
    // No dynamic constraints: the Ego is put 20 m behind the Target's reference point and takes
    // its speed, every step.
    let run = run(&scenario(&long_distance(r#"distance="20" freespace="false" continuous="true""#, "")));
    for t in [1.0, 5.0, 10.0] {
        let (e, g) = (at(&run, "Ego", t), at(&run, "Target", t));
        assert!(close(g.x - e.x, 20.0, 1e-6), "t={t}: {}", g.x - e.x);
        assert!(close(e.speed, 10.0, 1e-9));
    }
}

#[test]
fn time_gap_with_freespace_and_limits_settles() {
    // Time gap 1 s at 10 m/s = 10 m between the boxes (reference points 14.5 m apart); from 30 m
    // behind at the same speed the damped spring with 3 m/s² limits settles there well within
    // 15 s and never exceeds the limits.
    let c = r#"<DynamicConstraints maxAcceleration="3" maxDeceleration="3" maxSpeed="30"/>"#;
    let run = run(&scenario_from(&long_distance(r#"timeGap="1" freespace="true" continuous="true""#, c), 70.0, 10.0));
    let (e, g) = (at(&run, "Ego", 15.0), at(&run, "Target", 15.0));
    assert!(close(g.x - e.x, 14.5, 0.05), "{}", g.x - e.x);
    assert!(close(e.speed, 10.0, 0.02));
    for k in 1..1500 {
        let (a, b) = (at(&run, "Ego", (k - 1) as f64 * 0.01).speed, at(&run, "Ego", k as f64 * 0.01).speed);
        assert!((b - a).abs() <= 3.0 * 0.01 + 1e-9, "step {k}: {a} -> {b}");
    }
}

#[test]
fn non_continuous_action_ends_within_a_tenth_of_a_metre() {
    let c = r#"<DynamicConstraints maxAcceleration="3" maxDeceleration="3" maxSpeed="30"/>"#;
    let run = run(&scenario(&long_distance(r#"distance="20" freespace="false" continuous="false""#, c)));
    let end = event_time(&run, "KeepAction", "end").expect("action ends");
    let (e, g) = (at(&run, "Ego", end), at(&run, "Target", end));
    assert!((g.x - e.x - 20.0).abs() < 0.1 + 0.2, "{}", g.x - e.x);
}

fn acc_scenario(set_speed: f64) -> String {
    // The Ego carries an ACC (override mode, time gap 1 s) and is 90 m behind a Target at 10 m/s.
    let text = xosc(
        &format!(
            "{}{}<Private entityRef=\"Ego\"><PrivateAction><ActivateControllerAction longitudinal=\"true\" lateral=\"false\"/></PrivateAction></Private>",
            placed("Ego", 10.0, -1, 20.0),
            placed("Target", 100.0, -1, 10.0)
        ),
        "",
        &stop_at(40.0),
    );
    let controller = format!(
        r#"<ObjectController><Controller name="ACCController"><Properties><Property name="timeGap" value="1.0"/><Property name="mode" value="override"/><Property name="setSpeed" value="{set_speed}"/></Properties></Controller></ObjectController></ScenarioObject>"#
    );
    // Attach the controller to the Ego (the first ScenarioObject).
    text.replacen("</ScenarioObject>", &controller, 1)
}

#[test]
fn acc_follows_the_lead_at_minimum_distance_plus_time_gap() {
    // Following distance 3 m + 1 s × 10 m/s = 13 m between the boxes (reference points 17.5 m
    // apart), at the lead's speed.
    let run = run_with(&acc_scenario(20.0), &engine::Settings { step: 0.01, max_time: 40.0 });
    let (e, g) = (at(&run, "Ego", 39.0), at(&run, "Target", 39.0));
    assert!(close(e.speed, 10.0, 0.05), "{}", e.speed);
    assert!(close(g.x - e.x, 17.5, 0.5), "{}", g.x - e.x);
}

#[test]
fn acc_without_lead_cruises_at_set_speed() {
    // Set speed 5 m/s below the lead's: the gap only grows, so the ACC slows to its set speed
    // at 0.7 × max acceleration per (m/s) of error and keeps it.
    let run = run_with(&acc_scenario(5.0), &engine::Settings { step: 0.01, max_time: 40.0 });
    assert!(close(at(&run, "Ego", 30.0).speed, 5.0, 1e-6));
}

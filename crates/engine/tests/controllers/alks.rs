//! ALKSController (esmini's ALKS: its ACC controller under another name) on the straight fixture
//! road, against hand computations. The Ego here has maximum acceleration 5 m/s² and
//! deceleration 10 m/s² (see `common` for the rest: cars 4.5 m long, box centre 1.5 m ahead of
//! the reference point, lane -1 centred on y = -1.75, lane -2 on y = -5.25).
//!
//! The model, per step: with no vehicle ahead in its lane the speed approaches the set speed at
//! 0.7 × max acceleration per (m/s) of error, clipped to [-max deceleration, 0.7 × max
//! acceleration]; behind a lead it blends a distance term and a speed term towards a box gap of
//! 3 m + timeGap (1.5 s by default) × speed. Without a `mode` property it is additive: the
//! default controller moves the entity by the speed the controller set one step earlier, and a
//! speed that a storyboard action sets becomes the new set speed.

use crate::common::*;

const DT: f64 = 0.01;

fn activate(entity: &str) -> String {
    format!(r#"<Private entityRef="{entity}"><PrivateAction><ActivateControllerAction longitudinal="true" lateral="false"/></PrivateAction></Private>"#)
}

/// Give the Ego (the first ScenarioObject) an ALKSController with `properties` and the limits
/// 5 m/s² / 10 m/s².
fn with_alks(text: String, properties: &str) -> String {
    let controller = format!(
        r#"<ObjectController><Controller name="ALKSController"><Properties>{properties}</Properties></Controller></ObjectController></ScenarioObject>"#
    );
    text.replacen(r#"maxAcceleration="200" maxDeceleration="200""#, r#"maxAcceleration="5" maxDeceleration="10""#, 1).replacen(
        "</ScenarioObject>",
        &controller,
        1,
    )
}

fn settings(max_time: f64) -> engine::Settings {
    engine::Settings { step: DT, max_time }
}

/// Ego at s = 10 (20 m/s, lane -1); Target behind it at s = 0 in lane -2, standing: no lead.
fn free_road(properties: &str, stories: &str) -> String {
    let init = format!("{}{}{}{}", teleport("Ego", 10.0, -1), init_speed("Ego", "step", "time", 0.0, 20.0), activate("Ego"), teleport("Target", 0.0, -2));
    with_alks(xosc(&init, stories, &stop_at(30.0)), properties)
}

#[test]
fn alks_is_modelled_not_warned_about() {
    let run = run_with(&free_road("", ""), &settings(1.0));
    assert!(run.warnings.iter().all(|w| !w.to_string().contains("ALKSController")), "{:?}", run.warnings);
}

#[test]
fn free_road_keeps_the_activation_speed_and_the_lane() {
    // Additive mode: the set speed is the speed at activation, 20 m/s, held exactly.
    let run = run_with(&free_road("", ""), &settings(10.0));
    for t in [0.01, 1.0, 5.0, 10.0] {
        let e = at(&run, "Ego", t);
        assert!(close(e.speed, 20.0, 1e-9), "t {t}: {}", e.speed);
        assert!(close(e.x, 10.0 + 20.0 * t, 1e-6), "t {t}: {}", e.x);
        assert!(close(e.y, -1.75, 1e-9), "t {t}: {}", e.y);
    }
}

#[test]
fn override_mode_reaches_its_set_speed_at_the_comfort_acceleration() {
    // setSpeed 25 from 20: while 25 - v >= 1 the acceleration is the cap 0.7 × 5 = 3.5 m/s², so
    // after 100 steps v = 23.5; in override mode the controller moves the entity by its new
    // speed, x(1) = 10 + Σ_{k=1..100} (20 + 0.035 k) × 0.01 = 31.7675. Beyond 24 m/s the error
    // shrinks by 3.5 % a step: at 10 s the speed is 25.
    let props = r#"<Property name="mode" value="override"/><Property name="setSpeed" value="25"/>"#;
    let run = run_with(&free_road(props, ""), &settings(10.0));
    let e = at(&run, "Ego", 1.0);
    assert!(close(e.speed, 23.5, 1e-9), "{}", e.speed);
    assert!(close(e.x, 31.7675, 1e-6), "{}", e.x);
    assert!(close(at(&run, "Ego", 10.0).speed, 25.0, 1e-6));
}

#[test]
fn additive_mode_takes_a_storyboard_speed_as_its_new_set_speed() {
    // A step SpeedAction to 15 m/s at t > 2 becomes the set speed: the controller brakes at
    // its limit 10 m/s² while 3.5 × (v - 15) > 10 (v > 17.857), then closes the gap by 3.5 % a
    // step, never below 15, and holds 15.
    let action = speed_action("step", "time", 0.0, 15.0);
    let stories = story("Ego", &event("Slow", "overwrite", &action, &trigger(&sim_time(2.0, "greaterThan", "none", 0.0))));
    let run = run_with(&free_road("", &stories), &settings(12.0));
    let start = event_time(&run, "Slow", "start").expect("speed event starts");
    assert!(close(start, 2.01, 1e-9), "{start}");
    // The event starts when its trigger is seen at 2.01; the action acts in the next step,
    // where the controller takes 15 as its set speed and brakes one step from 20.
    assert!(close(at(&run, "Ego", start).speed, 20.0, 1e-9));
    assert!(close(at(&run, "Ego", start + 0.01).speed, 19.9, 1e-9), "{}", at(&run, "Ego", start + 0.01).speed);
    assert!(close(at(&run, "Ego", start + 0.11).speed, 18.9, 1e-9), "{}", at(&run, "Ego", start + 0.11).speed);
    let mut min = f64::MAX;
    let e = run.trace.entities.iter().find(|e| e.name == "Ego").expect("Ego");
    for s in e.samples.iter().flatten() {
        min = min.min(s.speed);
    }
    assert!(min >= 15.0 - 1e-9, "{min}");
    assert!(close(at(&run, "Ego", 12.0).speed, 15.0, 1e-6));
}

/// Ego at s = 10 (20 m/s, lane -1); Target at `target_s` in `lane` at `target_speed`.
fn with_target(target_s: f64, lane: i32, target_speed: f64, stories: &str, t_end: f64) -> String {
    let init = format!(
        "{}{}{}{}{}",
        teleport("Ego", 10.0, -1),
        init_speed("Ego", "step", "time", 0.0, 20.0),
        activate("Ego"),
        teleport("Target", target_s, lane),
        init_speed("Target", "step", "time", 0.0, target_speed)
    );
    with_alks(xosc(&init, stories, &stop_at(t_end)), "")
}

#[test]
fn slower_lead_in_the_lane_is_followed_at_its_speed_and_the_time_gap() {
    // Equilibrium behind a 10 m/s lead with set speed 20: the blend
    // 2.5 f - f (v - 20) - (1 - f)(v - 10) vanishes at v = 10 only for f = 0, i.e. a box gap
    // of 3 m + 1.5 s × 10 m/s = 18 m; reference points 18 + (1.5 + 2.25) + (2.25 - 1.5) = 22.5 m
    // apart.
    let run = run_with(&with_target(150.0, -1, 10.0, "", 80.0), &settings(80.0));
    let (e, g) = (at(&run, "Ego", 80.0), at(&run, "Target", 80.0));
    assert!(close(e.speed, 10.0, 0.01), "{}", e.speed);
    assert!(close(g.x - e.x, 22.5, 0.05), "{}", g.x - e.x);
    // It never gets closer than the minimum distance.
    let ego = run.trace.entities.iter().find(|e| e.name == "Ego").expect("Ego");
    let tgt = run.trace.entities.iter().find(|e| e.name == "Target").expect("Target");
    for (a, b) in ego.samples.iter().zip(&tgt.samples) {
        if let (Some(a), Some(b)) = (a, b) {
            assert!(b.x - a.x - 4.5 > 3.0, "{}", b.x - a.x - 4.5);
        }
    }
}

#[test]
fn a_cut_in_is_followed_from_the_step_the_target_enters_the_lane() {
    // The Target (15 m/s, lane -2, 50 m ahead) changes to lane -1 over 2 s (sinusoidal) from
    // t = 2.01: its offset 3.5 (1 - cos(π τ / 2)) / 2, τ = t - 2.01, reaches half a lane at
    // τ = 1, t = 3.01. Until then it is in another lane and too far for the close-range check
    // (box gap 45.5 - 5 t > 1 + 4.5 + 0.5 × 5), so the Ego keeps 20 m/s; from the step its
    // lane becomes -1 the gap (≈ 30 m) is below 3 + 1.5 × 20 = 33 m and the Ego brakes. It
    // ends at the lead's speed, 15 m/s, 3 + 1.5 × 15 = 25.5 m behind it (box gap).
    let lc = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="2" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-1"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let stories = story("Target", &event("CutIn", "overwrite", lc, &trigger(&sim_time(2.0, "greaterThan", "none", 0.0))));
    let run = run_with(&with_target(60.0, -2, 15.0, &stories, 60.0), &settings(60.0));
    assert!(close(event_time(&run, "CutIn", "start").expect("cut-in starts"), 2.01, 1e-9));
    for t in [1.0, 2.5, 3.0] {
        assert!(close(at(&run, "Ego", t).speed, 20.0, 1e-9), "t {t}: {}", at(&run, "Ego", t).speed);
    }
    // The first braking step: 3.01 when the crossing at exactly half a lane already counts as
    // lane -1, else the next step.
    let ego = run.trace.entities.iter().find(|e| e.name == "Ego").expect("Ego");
    let first = ego.samples.iter().position(|s| s.is_some_and(|s| s.speed < 20.0 - 1e-9)).expect("Ego brakes");
    let t_first = first as f64 * DT;
    assert!((3.01 - 1e-9..=3.02 + 1e-9).contains(&t_first), "{t_first}");
    let (e, g) = (at(&run, "Ego", 60.0), at(&run, "Target", 60.0));
    assert!(close(e.speed, 15.0, 0.01), "{}", e.speed);
    assert!(close(g.x - e.x - 4.5, 25.5, 0.05), "{}", g.x - e.x - 4.5);
}

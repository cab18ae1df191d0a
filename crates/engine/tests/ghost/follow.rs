//! FollowGhostController and FollowReferenceController on the straight fixture road (see
//! `common`: road along +x from the origin, lane -1's centre at y = -1.75, lane -2's at
//! y = -5.25), against hand computations: the ghost runs the storyboard `headstart` seconds
//! early, the Ego follows its trail or tracks it with a damped spring.

use crate::common::*;

const HEADSTART: f64 = 2.0;

fn activate() -> String {
    r#"<Private entityRef="Ego"><PrivateAction><ActivateControllerAction longitudinal="true" lateral="true"/></PrivateAction></Private>"#.to_string()
}

/// The Ego (first ScenarioObject) gets an inline controller with these properties.
fn with_controller(text: String, properties: &str) -> String {
    let c = format!(r#"<ObjectController><Controller name="driver"><Properties>{properties}</Properties></Controller></ObjectController></ScenarioObject>"#);
    text.replacen("</ScenarioObject>", &c, 1)
}

fn follow_ghost_props() -> String {
    format!(
        r#"<Property name="esminiController" value="FollowGhostController"/><Property name="headstartTime" value="{HEADSTART}"/><Property name="followMode" value="position"/><Property name="lookaheadSpeed" value="0.5"/><Property name="minLookaheadSpeed" value="7"/><Property name="lookaheadSteering" value="0.5"/><Property name="minLookaheadSteering" value="7"/><Property name="steeringSpeedInertia" value="0.02"/>"#
    )
}

/// Ego at s = 50 in lane -1 at `speed`; the story gives it `events`.
fn ghost_scenario(speed: f64, events: &str, end: f64) -> String {
    let init = format!("{}{}{}{}", teleport("Ego", 50.0, -1), init_speed("Ego", "step", "time", 0.0, speed), teleport("Target", 900.0, 1), activate());
    let stories = if events.is_empty() { String::new() } else { story("Ego", events) };
    with_controller(xosc(&init, &stories, &stop_at(end)), &follow_ghost_props())
}

fn settings(max: f64) -> engine::Settings {
    engine::Settings { step: 0.01, max_time: max }
}

#[test]
fn the_ghost_starts_headstart_early_and_leads_by_headstart_times_speed() {
    let run = run_with(&ghost_scenario(10.0, "", 8.0), &settings(20.0));
    assert!(close(run.trace.start, -HEADSTART, 1e-12), "{}", run.trace.start);
    assert!(run.trace.entities.iter().any(|e| e.name == "Ego_ghost"), "the trace names the ghost as esmini does");
    assert!(!run.warnings.iter().any(|w| w.to_string().contains("not modelled")), "{:?}", run.warnings);
    // During the head start only the ghost moves: 10 m/s for 2 s.
    let (e0, g0) = (at(&run, "Ego", 0.0), at(&run, "Ego_ghost", 0.0));
    assert!(close(e0.x, 50.0, 1e-9), "{}", e0.x);
    assert!(close(g0.x, 50.0 + HEADSTART * 10.0, 1e-6), "{}", g0.x);
    // Then the Ego drives the ghost's trail at the ghost's speed: it stays headstart·speed behind,
    // in its lane, straight.
    for t in [1.0, 4.0, 8.0] {
        let (e, g) = (at(&run, "Ego", t), at(&run, "Ego_ghost", t));
        assert!(close(g.x - e.x, HEADSTART * 10.0, 1e-6), "t={t}: gap {}", g.x - e.x);
        assert!(close(e.x, 50.0 + 10.0 * t, 1e-6), "t={t}: {}", e.x);
        assert!(close(e.y, -1.75, 1e-9) && close(e.speed, 10.0, 1e-9), "t={t}: {} {}", e.y, e.speed);
    }
}

#[test]
fn simulation_time_triggers_fire_headstart_early_for_the_ghost() {
    // "SimulationTime > 1" moves to "> 1 - 2": the ghost's lane change starts at the first step
    // after −1, at −0.99 (rising edge).
    let lc = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="2" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let ev = event("Change", "overwrite", lc, &trigger(&sim_time(1.0, "greaterThan", "rising", 0.0)));
    let run = run_with(&ghost_scenario(10.0, &ev, 12.0), &settings(20.0));
    let started = event_time(&run, "Change", "start").expect("lane change event starts");
    assert!(close(started, -0.99, 1e-9), "{started}");
    // The lane change took the ghost, not the Ego: at 0 the Ego has not moved, the ghost is
    // half way (sinusoidal, 2 s, started at −0.99).
    let g = at(&run, "Ego_ghost", 0.0);
    let half = -1.75 - 3.5 * (1.0 - (std::f64::consts::PI * 0.99 / 2.0).cos()) / 2.0;
    assert!(close(g.y, half, 0.02), "{} vs {half}", g.y);
    assert!(close(at(&run, "Ego", 0.0).y, -1.75, 1e-9));
}

#[test]
fn a_lane_change_of_the_ghost_is_followed_smoothly_into_the_target_lane() {
    let lc = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="2" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let ev = event("Change", "overwrite", lc, &trigger(&sim_time(3.0, "greaterThan", "rising", 0.0)));
    let run = run_with(&ghost_scenario(10.0, &ev, 14.0), &settings(20.0));
    // The ghost changes lanes in [1, 3] s; the Ego, 20 m behind on its trail, about 2 s later.
    // It moves from lane -1 to lane -2 without leaving the band between the two lane centres by
    // more than 0.2 m (it aims at the trail 7 m ahead, so it cuts in and overshoots a little),
    // turning gently, and ends on lane -2's centre.
    let mut prev_h = at(&run, "Ego", 0.0).h;
    let mut t = 0.01;
    while t < 14.0 {
        let e = at(&run, "Ego", t);
        assert!(e.y <= -1.75 + 0.02 && e.y >= -5.25 - 0.2, "t={t}: y {}", e.y);
        let dh = (e.h - prev_h + std::f64::consts::PI).rem_euclid(2.0 * std::f64::consts::PI) - std::f64::consts::PI;
        // A lane change of 3.5 m in 2 s at 10 m/s turns by at most ~0.27 rad/s.
        assert!(dh.abs() < 0.5 * 0.01, "t={t}: heading step {dh}");
        prev_h = e.h;
        t += 0.01;
    }
    let end = at(&run, "Ego", 14.0);
    assert!(close(end.y, -5.25, 0.02), "{}", end.y);
    assert_eq!(end.road.map(|r| r.lane_id), Some(-2));
    // The Ego passes where the ghost was: at every one of its positions before and well after the
    // manoeuvre, the ghost went through the same point (same y where it had the same x).
    let ghost = &run.trace.entities.iter().find(|e| e.name == "Ego_ghost").expect("ghost").samples;
    let ghost_y_at = |x: f64| {
        let w = ghost.windows(2).flat_map(|p| match (p[0], p[1]) {
            (Some(a), Some(b)) if a.x <= x && x <= b.x && b.x > a.x => Some(a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)),
            _ => None,
        });
        w.into_iter().next().expect("the ghost passed x")
    };
    for t in [0.5, 2.0, 8.0, 10.0, 13.0] {
        let e = at(&run, "Ego", t);
        assert!(close(e.y, ghost_y_at(e.x), 0.02), "t={t}: {} vs {}", e.y, ghost_y_at(e.x));
    }
}

fn follow_reference_scenario(ghost_speed: f64, events: &str, end: f64) -> String {
    let init = format!("{}{}{}{}", teleport("Ego", 50.0, -1), init_speed("Ego", "step", "time", 0.0, ghost_speed), teleport("Target", 900.0, 1), activate());
    let stories = if events.is_empty() { String::new() } else { story("Ego", events) };
    let props = r#"<Property name="esminiController" value="FollowReferenceController"/><Property name="speedControlStiffness" value="1.0"/>"#;
    with_controller(xosc(&init, &stories, &stop_at(end)), props)
}

#[test]
fn follow_reference_tracks_its_ghost_with_a_critically_damped_spring() {
    // No head start; the ghost and the Ego both start at 10 m/s. Each step the ghost moves
    // first, then the Ego measures dx = its position − the ghost's and accelerates by
    // a = −k·dx − 2√k·(v − v_ghost), k = 1, then moves. At rest the Ego steers to where the ghost
    // already is, so it settles one step's travel (0.1 m) ahead; it starts 0.1 m short of that
    // with equal speeds, so dx(t) = −0.1·(1 + t)·e^(−t) (critically damped), and the recorded
    // gap is dx + v·dt.
    let run = run_with(&follow_reference_scenario(10.0, "", 8.0), &settings(20.0));
    assert!(close(run.trace.start, 0.0, 0.0));
    for t in [1.0, 3.0, 8.0] {
        let (e, g) = (at(&run, "Ego", t), at(&run, "Ego_ghost", t));
        let want = 0.1 - 0.1 * (1.0 + t) * (-t).exp();
        assert!(close(e.x - g.x, want, 2e-3), "t={t}: {} vs {want}", e.x - g.x);
        // v − v_ghost = d(dx)/dt = 0.1·t·e^(−t).
        assert!(close(e.y, -1.75, 1e-9) && close(e.speed, 10.0 + 0.1 * t * (-t).exp(), 1e-3), "t={t}: {} {}", e.y, e.speed);
    }
}

#[test]
fn follow_reference_catches_up_like_a_critically_damped_spring() {
    // The Ego starts at rest (its Init speed action goes to the ghost, whose copy accelerates
    // it at once to 10 m/s; the Ego's own copy is overridden by the controller): continuous
    // solution e(t) = x_ego − x_ghost = −10·t·e^(−t), so −3.68 m at 1 s and −1.35 m at 2 s;
    // Euler steps of 0.01 s and the one-step lead (+0.1 m at rest) shift it by a few cm.
    let lc = r#"<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"#;
    let ev = event("Go", "overwrite", lc, &trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0)));
    let run = run_with(&follow_reference_scenario(0.0, &ev, 10.0), &settings(20.0));
    let gap = |t: f64| at(&run, "Ego", t).x - at(&run, "Ego_ghost", t).x;
    let expected = |t: f64| -10.0 * t * (-t).exp();
    for t in [0.5, 1.0, 2.0, 4.0] {
        assert!(close(gap(t), expected(t), 0.15), "t={t}: {} vs {}", gap(t), expected(t));
    }
    assert!(close(gap(10.0), 0.1, 0.01), "{}", gap(10.0));
    // Speed error −de/dt = 10·(1 − t)·e^(−t): 0.004 m/s at 10 s.
    assert!(close(at(&run, "Ego", 10.0).speed, 10.0 + 10.0 * 9.0 * (-10.0_f64).exp(), 2e-3));
}

#[test]
fn follow_reference_follows_a_lane_change_of_its_ghost() {
    let lc = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="3" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    let ev = event("Change", "overwrite", lc, &trigger(&sim_time(1.0, "greaterThan", "rising", 0.0)));
    let run = run_with(&follow_reference_scenario(10.0, &ev, 10.0), &settings(20.0));
    let end = at(&run, "Ego", 10.0);
    assert!(close(end.y, -5.25, 0.01), "{}", end.y);
    assert_eq!(end.road.map(|r| r.lane_id), Some(-2));
    for k in 0..1000 {
        let e = at(&run, "Ego", k as f64 * 0.01);
        assert!(e.y <= -1.75 + 0.05 && e.y >= -5.25 - 0.1, "t={}: {}", k as f64 * 0.01, e.y);
    }
}

#[test]
fn time_mode_follows_the_ghost_headstart_seconds_behind() {
    // followMode "time": target speed and steering point are where the ghost was headstart minus
    // the look-ahead ago; on a straight road at a constant 10 m/s that is the ghost's own speed
    // straight ahead, so the Ego keeps the 20 m it starts with.
    let props = follow_ghost_props().replace(r#"value="position""#, r#"value="time""#);
    let init = format!("{}{}{}{}", teleport("Ego", 50.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0), teleport("Target", 900.0, 1), activate());
    let run = run_with(&with_controller(xosc(&init, "", &stop_at(6.0)), &props), &settings(20.0));
    for t in [1.0, 6.0] {
        let (e, g) = (at(&run, "Ego", t), at(&run, "Ego_ghost", t));
        assert!(close(g.x - e.x, HEADSTART * 10.0, 1e-6), "t={t}: gap {}", g.x - e.x);
        assert!(close(e.y, -1.75, 1e-9) && close(e.speed, 10.0, 1e-9));
    }
}

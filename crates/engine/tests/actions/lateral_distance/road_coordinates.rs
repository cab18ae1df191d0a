//! LateralDistanceAction in the road coordinate system on the straight fixture road (lane -1's
//! centre at y = -1.75, lane -2's at y = -5.25; cars 2 m wide), against hand computations: the
//! Ego drives beside the Target and keeps a lateral distance to its left or right.

use crate::common::*;

fn lat_distance(attrs: &str, constraints: &str) -> String {
    format!(
        r#"<PrivateAction><LateralAction><LateralDistanceAction entityRef="Target" coordinateSystem="road" {attrs}>{constraints}</LateralDistanceAction></LateralAction></PrivateAction>"#
    )
}

/// Ego in lane -1, Target in lane -2, side by side at s = 100, both 10 m/s.
fn scenario(action: &str) -> String {
    scenario_until(action, 5.0)
}

fn scenario_until(action: &str, end: f64) -> String {
    let init = format!("{}{}", placed("Ego", 100.0, -1, 10.0), placed("Target", 100.0, -2, 10.0));
    let stories = story("Ego", &event("Keep", "overwrite", action, &trigger(&sim_time(0.0, "greaterOrEqual", "none", 0.0))));
    xosc(&init, &stories, &stop_at(end))
}

#[test]
fn without_limits_the_actor_jumps_onto_the_distance() {
    // Left of the Target with 1 m between the boxes: t = -5.25 + 1 + (2 + 2) / 2 = -2.25.
    let run = run(&scenario(&lat_distance(r#"distance="1" freespace="true" continuous="true" displacement="leftToReferencedEntity""#, "")));
    for t in [0.5, 2.0, 4.0] {
        assert!(close(at(&run, "Ego", t).y, -2.25, 1e-6), "t={t}: {}", at(&run, "Ego", t).y);
    }
}

#[test]
fn right_of_the_reference_without_freespace() {
    // Reference points 0.5 m apart, to the right: t = -5.25 - 0.5 = -5.75 (the Ego crosses over).
    let run = run(&scenario(&lat_distance(r#"distance="0.5" freespace="false" continuous="true" displacement="rightToReferencedEntity""#, "")));
    assert!(close(at(&run, "Ego", 1.0).y, -5.75, 1e-6), "{}", at(&run, "Ego", 1.0).y);
}

#[test]
fn max_speed_limits_the_sideways_motion() {
    // 0.5 m to cover at 0.5 m/s: about 1 s (plus the first step, which only records the
    // position); never faster than 0.5 m/s sideways; forward speed sqrt(10² - 0.5²) meanwhile.
    let c = r#"<DynamicConstraints maxSpeed="0.5"/>"#;
    let run = run(&scenario(&lat_distance(r#"distance="1" freespace="true" continuous="true" displacement="leftToReferencedEntity""#, c)));
    for k in 1..500 {
        let (a, b) = (at(&run, "Ego", (k - 1) as f64 * 0.01), at(&run, "Ego", k as f64 * 0.01));
        assert!((b.y - a.y).abs() <= 0.5 * 0.01 + 1e-9, "step {k}: {} -> {}", a.y, b.y);
    }
    let half = at(&run, "Ego", 0.51);
    assert!(close(half.y, -1.75 - 0.5 * 0.5, 0.011), "{}", half.y);
    let dx = at(&run, "Ego", 0.51).x - at(&run, "Ego", 0.50).x;
    assert!(close(dx, (100.0f64 - 0.25).sqrt() * 0.01, 1e-6), "{dx}");
    assert!(close(at(&run, "Ego", 2.0).y, -2.25, 1e-6));
}

#[test]
fn max_acceleration_spring_settles_and_a_single_shot_ends() {
    // Critically damped spring (stiffness 0.4 × 2 m/s²): the lateral acceleration never exceeds
    // 2 m/s² and the non-continuous action ends once within 0.01 m of the wanted t.
    let c = r#"<DynamicConstraints maxAcceleration="2" maxSpeed="5"/>"#;
    // (0.5 m · (1 + ωt)·e^(-ωt) < 0.01 m with ω = √0.8 takes about 7.4 s.)
    let run = run(&scenario_until(&lat_distance(r#"distance="1" freespace="true" continuous="false" displacement="leftToReferencedEntity""#, c), 15.0));
    let end = event_time(&run, "KeepAction", "end").expect("the action ends");
    assert!(end > 5.0 && end < 10.0, "{end}");
    assert!(close(at(&run, "Ego", end).y, -2.25, 0.011), "{}", at(&run, "Ego", end).y);
    for k in 2..((end / 0.01) as usize) {
        let y = |i: usize| at(&run, "Ego", i as f64 * 0.01).y;
        let acc = (y(k) - 2.0 * y(k - 1) + y(k - 2)) / 1e-4;
        assert!(acc.abs() <= 2.0 + 1e-6, "step {k}: {acc}");
    }
}

#[test]
fn without_limits_the_actor_takes_the_lane_it_lands_in() {
    // Ego and Target both in lane -1 (t = -1.75); 5 m to the Target's left is t = 3.25, in
    // lane 1: esmini (GetDesiredRoadPos, a fresh XYZ2TrackPos) puts the Ego in lane 1 at offset
    // 1.5 from its centre, not in lane -1 at offset 5; it goes on along +x all the same.
    let init = format!("{}{}", placed("Ego", 20.0, -1, 10.0), placed("Target", 20.0, -1, 10.0));
    let action = lat_distance(r#"distance="5" freespace="false" continuous="true" displacement="leftToReferencedEntity""#, "");
    let stories = story("Ego", &event("Keep", "overwrite", &action, &trigger(&sim_time(0.5, "greaterThan", "none", 0.0))));
    let run = run(&xosc(&init, &stories, &stop_at(6.0)));
    for (t, x) in [(1.0, 30.0), (4.0, 60.0)] {
        let e = at(&run, "Ego", t);
        let road = e.road.expect("on the road");
        assert!(close(e.x, x, 1e-6) && close(e.y, 3.25, 1e-6), "t={t}: {e:?}");
        assert!(road.lane_id == 1 && close(road.lane_offset, 1.5, 1e-6), "t={t}: {road:?}");
    }
}

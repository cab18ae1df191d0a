//! An AccelerationCondition reads the entity's acceleration vector — the change of its world
//! velocity over the last step (ScenarioEngine::prepareGroundTruth) — as esmini's
//! TrigByAcceleration::CheckCondition does: without a direction, Position::GetAcc (the
//! vector's length, signed as its component along the heading), with one its component along
//! the entity's axes (GetAccLong, GetAccLat). So a car at constant speed entering a curve has
//! a centripetal acceleration. Fixture `acceleration_condition_curve.xosc` on
//! `curve_r50.xodr` (50 m straight, a left arc of radius 50 m): Ego at 10 m/s reaches the arc
//! at 3 s (v²/r = 2 m/s²); four events wait for acceleration < -1.5, lateral > 1.5,
//! longitudinal < -1.5 and > 1.5. Expected values: esmini 3.6.0 on the same fixture (lateral
//! and unsigned-positive start at 3.02 s, the other two never).

use crate::common::*;

#[test]
fn an_acceleration_condition_sees_the_centripetal_acceleration() {
    let run = run_fixture("acceleration_condition_curve.xosc", "curve_r50.xodr");
    let start = |name: &str| run.trace.events.iter().find(|ev| ev.element == name && ev.to == "running").map(|ev| ev.time);
    assert!(start("Lateral").is_some_and(|t| close(t, 3.02, 1e-9)), "{:?}", start("Lateral"));
    assert!(start("Positive").is_some_and(|t| close(t, 3.02, 1e-9)), "{:?}", start("Positive"));
    assert_eq!(start("Signed"), None);
    assert_eq!(start("Longitudinal"), None);
}

/// Position::GetAcc signs the magnitude with CommonMini's SIGN, +1 for a component of 0: a
/// purely sideways acceleration (a step lane offset) is positive both when the entity jumps
/// sideways and when it stops moving sideways. Fixture `acceleration_sideways_sign.xosc`:
/// esmini 3.6.0 starts Up (> 2.06) at 1.02 s and Down (< -2.06) never.
#[test]
fn a_purely_sideways_acceleration_counts_as_positive() {
    let run = run_fixture_on("acceleration_sideways_sign.xosc", "straight.xodr", 3.0);
    assert!(event_time(&run, "Up", "start").is_some_and(|t| close(t, 1.02, 1e-9)), "{:?}", event_time(&run, "Up", "start"));
    assert_eq!(event_time(&run, "Down", "start"), None);
}

//! A lane change to a lane the road does not have. esmini (LatLaneChangeAction::Start,
//! Position::ForceLaneId, a failing SetLanePos) measures the missing lane as one of width 0 at
//! the road's edge and applies the offset from its centre in the lane the entity is in: the
//! entity jumps half a lane towards the road's centre, then drifts back to its lane centre over
//! the action's time. Found by crates/difftest; the numbers are esmini 3.6.0's run of this
//! scenario (written by `write_for_esmini`).

use crate::common::*;

/// Ego on lane -2, the last right lane of the fixture road (3.5 m wide, centre y = -5.25), at
/// 10 m/s from s = 50; at 1 s a linear lane change one lane further right over 2 s.
fn scenario() -> String {
    let change = r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="linear" value="2" dynamicsDimension="time"/><LaneChangeTarget><RelativeTargetLane entityRef="Ego" value="-1"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#;
    xosc(
        &format!("{}{}", placed_in_one_private("Ego", 50.0, -2, 10.0), teleport("Target", 300.0, -1)),
        &story("Ego", &event("Change", "parallel", change, &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)))),
        &stop_at(4.0),
    )
}

#[test]
fn a_missing_target_lane_moves_as_esmini_moves() {
    let run = run(&scenario());
    // esmini: y = -5.25 until the action starts, then half a lane less one step of the 2 s
    // drift, and back on -5.25 at its end
    for (t, y) in [(1.0, -5.25), (1.01, -3.50875), (1.02, -3.5175), (2.01, -4.38375), (3.0, -5.25), (3.5, -5.25)] {
        let s = at(&run, "Ego", t);
        assert!((s.y - y).abs() < 1e-3, "t = {t}: y = {} (esmini {y})", s.y);
    }
    assert!(run.warnings.iter().any(|w| w.message.contains("lane -3 does not exist")), "{:?}", run.warnings);
}

#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("missing_target_lane.xosc"), scenario()).expect("write");
}

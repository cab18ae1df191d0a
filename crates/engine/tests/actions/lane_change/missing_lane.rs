//! A lane change to a lane the road does not have. esmini (LatLaneChangeAction::Start,
//! Position::ForceLaneId, a failing SetLanePos) measures the missing lane as one of width 0 at
//! the road's edge and applies the offset from its centre in the lane the entity is in: the
//! entity jumps half a lane towards the road's centre, then drifts back to its lane centre over
//! the action's time. Found by crates/difftest; the numbers are esmini 3.6.0's run of this
//! scenario (written by `write_for_esmini`).

use crate::common::*;

/// Ego on lane `lane` at 10 m/s from s = 50; at 1 s a linear lane change to `target` (a
/// LaneChangeTarget's content) over 2 s.
fn lane_change_from(lane: i32, target: &str) -> String {
    let change = format!(
        r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="linear" value="2" dynamicsDimension="time"/><LaneChangeTarget>{target}</LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#
    );
    xosc(
        &format!("{}{}", placed_in_one_private("Ego", 50.0, lane, 10.0), teleport("Target", 300.0, -1)),
        &story("Ego", &event("Change", "parallel", &change, &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)))),
        &stop_at(4.0),
    )
}

/// Ego on lane -2, the last right lane of the fixture road (3.5 m wide, centre y = -5.25): a
/// lane change one lane further right.
fn scenario() -> String {
    lane_change_from(-2, r#"<RelativeTargetLane entityRef="Ego" value="-1"/>"#)
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

/// Ego on lane -1: a lane change to lane 2, which the fixture road does not have, on the other
/// side of the centre line.
fn scenario_across() -> String {
    lane_change_from(-1, r#"<AbsoluteTargetLane value="2"/>"#)
}

/// In the first step esmini's failed SetLanePos (LatLaneChangeAction::Step) keeps the offset
/// made for the missing lane 2 (its sign) and applies it in lane -1: for one frame the entity is
/// on the far side of its lane; from the next step the offset has lane -1's sign.
#[test]
fn a_missing_target_lane_across_the_centre_line_flips_for_one_step() {
    let run = run(&scenario_across());
    // esmini 3.6.0 (x, y, heading): lane -1's centre until the start, one frame near the road's
    // right edge (the offset from the phantom lane's centre, about -5.25 m, in lane -1), then
    // on the left lane's side, drifting back to lane -1's centre by 3 s
    let rows = [
        ("Ego", 1.0, 60.0, -1.75, 0.0),
        ("Ego", 1.01, 60.096493, -6.97375, 6.017573),
        ("Ego", 1.02, 60.192986, 3.4475, 6.017573),
        ("Ego", 1.5, 64.82466, 2.1875, 6.017573),
        ("Ego", 2.5, 74.47398, -0.4375, 6.017573),
        ("Ego", 3.0, 79.29864, -1.75, 0.0),
    ];
    assert_esmini_poses(&run, &rows, 1e-3, 1e-4);
}

#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("missing_target_lane.xosc"), scenario()).expect("write");
    std::fs::write(fixtures().join("missing_target_lane_across.xosc"), scenario_across()).expect("write");
}

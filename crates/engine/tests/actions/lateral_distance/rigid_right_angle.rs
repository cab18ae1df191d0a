//! A heading at a right angle to the road leaves esmini's rotation matrices a micro-radian to
//! one side, and that side decides which way the entity drives. Position::SetHeading (the
//! rigid LateralDistanceAction's atan2 of its jump) evaluates the orientation with an absolute
//! heading (EvaluateHPR, H_ABS): R0R12EulerAngles composes the road's rotation with the turn
//! from it, guarding a cosine under 1e-6 to ±1e-6, and CalcRelAnglesFromRoadAndAbsAngles finds
//! the relative heading back from that; MoveAlongS then goes backward only for a relative
//! heading strictly between π/2 and 3π/2 (IsAngleForward). A jump across a road written with
//! a rounded heading (hdg 3.1415926536, a hair past π) is a hair more than a right angle from
//! the road, which the plain difference calls backward; esmini's matrices call it forward.
//!
//! Fixture `lat_distance_rigid_right_angle.xosc` on straight_west.xodr (a road along −x from
//! x = 1000): the Ego stands on lane −2 at s 40, the Target on the same lane at s 20; at 1 s the
//! Ego is told to keep 3 m right of the Target and jumps there (heading π/2 + 1e-6); from 2 s
//! it drives at 5 m/s, forward along s (x decreasing). esmini 3.6.0's numbers.

use crate::common::oracle::esmini_rows;
use crate::common::oracle::run_fixture_scenario;
use crate::common::*;

#[test]
fn a_jump_at_a_right_angle_to_the_road_then_drives_forward_as_esmini_decides() {
    let run = run_fixture_scenario("lat_distance_rigid_right_angle.xosc", 10.0);
    let jump = at(&run, "Ego", 1.03);
    assert!(close(jump.x, 960.0, 1e-6) && close(jump.y, 8.25, 1e-6), "{jump:?}");
    // esmini logs 1.570797: π/2 pushed 1e-6 off by the gimbal-lock guard.
    assert!(close(jump.h, 1.570797, 1e-6), "{}", jump.h);
    // Forward along s (−x), not back towards x = 970.
    let end = at(&run, "Ego", 4.0);
    assert!(close(end.x, 950.05, 1e-6) && close(end.y, 8.25, 1e-6), "{end:?}");
    // The whole run's positions against esmini's (the heading of the standing car after the
    // jump is esmini's atan2 of a rounding error, not compared).
    if let Some(rows) = esmini_rows("lat_distance_rigid_right_angle.xosc") {
        for r in rows.iter().filter(|r| r.entity == "Ego" && r.time >= 0.0) {
            let s = at(&run, "Ego", r.time);
            assert!(close(s.x, r.x, 1e-3) && close(s.y, r.y, 1e-3), "t {}: esmini ({}, {}), engine ({}, {})", r.time, r.x, r.y, s.x, s.y);
        }
    }
}

//! A car reversing onto an untimed NURBS curve whose first control point gives a heading:
//! esmini's NurbsShape::EvaluateInternal takes each evaluated point's position mode from the
//! first control point (the first whose parameter the point has passed is always the first),
//! so FollowTrajectoryAction::Start finds the heading set explicitly wherever the action starts.
//! The entity faces the blended control-point heading, not the curve turned by π, and moves by
//! how that heading lies to the curve's (the same heading: backwards along it, as the speed
//! says). Found by crates/difftest (s56056_00180, where the engine turned the car by π and
//! drove it the other way along the curve).
//!
//! Fixture `trajectory_nurbs_reverse_first_heading.xosc` on straight.xodr: Reverser at −3 m/s
//! starts at 0.5 s, 15 m into an order-2 curve from x 60 (h 3.0) through x 40 to x 20: it
//! jumps there facing about 0.19 and backs towards x 60, its heading swinging as the control
//! points' headings blend. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn reversing_onto_a_nurbs_curve_faces_its_blended_control_point_heading() {
    assert_fixture_matches_esmini(
        "trajectory_nurbs_reverse_first_heading.xosc",
        3.5,
        &[
            ("Reverser", 0.52, 45.030047, -1.787425, 0.189760),
            ("Reverser", 1.0, 46.470042, -1.783825, 0.313961),
            ("Reverser", 3.5, 53.970019, -1.765075, 1.463711),
        ],
    );
}

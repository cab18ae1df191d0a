//! An ACC car stopped at a road end and then placed by a timed FollowTrajectory takes the
//! trajectory's speed: in esmini's ScenarioEngine::step the storyboard steps first
//! (FollowTrajectoryAction::Start → SetTrajectoryS → XYZ2TrackPos, which sets or clears
//! POS_STATUS_END_OF_ROAD from closestPointInside; with timing it SetSpeed(trajectory speed)),
//! then an object whose END_OF_ROAD bit is set and that does not move gets SetSpeed(0), then the
//! controllers run (ControllerACC: GetSpeed() ≠ currentSpeed_ → setSpeed_ = GetSpeed()). The jump
//! clears the bit, so the ACC sees the trajectory's speed and accelerates. The engine kept the
//! road-end status from the ACC's last own move, set the speed to 0 and the car stayed where the
//! trajectory put it. Found by crates/difftest (s63063_00770).
//!
//! Fixture `acc_road_end_then_trajectory.xosc` on crossing.xodr: Car1 (ACCController, override, set speed 11)
//! starts on road 1 at x 281.93 facing along s on lane 1 at 13.83 m/s and stops at the road end
//! (x 320) by 5.2 s; at 5.2 s a FollowTrajectoryAction (follow mode, relative timing, scale
//! 1.21, offset -0.73, initialDistanceOffset 20.91) puts it at x 260.82 facing back along the
//! road, and from there it speeds up by 0.07 m/s a step. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn an_acc_car_stopped_at_a_road_end_takes_a_timed_trajectory_speed() {
    assert_fixture_matches_esmini(
        "acc_road_end_then_trajectory.xosc",
        6.51,
        &[
            ("Car1", 5.2, 320.000000, 1.750000, 0.000000),
            ("Car1", 5.21, 260.815280, 1.750000, 3.140012),
            ("Car1", 6.0, 258.544883, 1.750000, 3.139846),
            ("Car1", 6.5, 254.850423, 1.750000, 3.139572),
        ],
    );
}

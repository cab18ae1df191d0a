//! A timed trajectory's start speed counts as set: FollowTrajectoryAction::Start gives the car
//! the trajectory's start speed with Object::SetSpeed, which marks the speed as set (the SPEED
//! dirty bit), so ScenarioEngine::prepareGroundTruth derives no speed from the step's
//! displacement, also when the action is stopped in the same step. The engine read the jump
//! back to the trajectory's start as a speed. Found by a helper on s70070_00452.
//!
//! Fixture `timed_trajectory_start_speed_counts_as_set.xosc` on difftest_straight.xodr: a timed
//! clothoid (start speed 0) starts at 0.01 s and a lane change starting in the same step stops
//! it. The car stays at x 1531.45 with speed 0 to the end (10.22 s); the engine had it drive on
//! at 29.25 m/s. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;
use crate::common::*;

#[test]
fn a_timed_trajectory_start_speed_is_not_overwritten_by_the_jump() {
    let run = assert_fixture_matches_esmini(
        "timed_trajectory_start_speed_counts_as_set.xosc",
        10.22,
        &[("Car0", 0.02, 1531.45, -5.25, 0.0), ("Car0", 10.0, 1531.45, -5.25, 0.0)],
    );
    assert!(close(at(&run, "Car0", 0.02).speed, 0.0, 1e-9), "speed at 0.02 s: {}", at(&run, "Car0", 0.02).speed);
}

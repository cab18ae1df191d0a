//! A LoomingController's lane lock outlasts its own steps: ControllerLooming::Step calls
//! SetLockOnLane(true) and nothing clears it, so every later SetInertiaPos (a
//! FollowTrajectoryAction's moves and its last step) runs XYZ2TrackPos's lockOnLane_ branch:
//! the lane stays, and the offset is measured from its centre. The engine placed the car on the
//! trajectory without the lock, so it changed lanes and took the cars of the other lane as its
//! lead. Found by a helper on s75075_00680, s77077_00376 and s77077_00832.
//!
//! Fixture `looming_lock_through_trajectory.xosc` on straight.xodr: Ego, a Looming controller
//! on the longitudinal domain (set speed 15 m/s), follows a polyline from lane -1 across lane
//! -2 from 1 s. In esmini it stays in lane -1 throughout. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_lane_stays_locked_on_the_trajectory() {
    assert_fixture_matches_esmini(
        "looming_lock_through_trajectory.xosc",
        11.0,
        &[("Ego", 2.36, 54.085983, 3.835413, 0.712808), ("Ego", 6.4, 50.304487, 3.811526, 6.181230), ("Ego", 9.0, 89.008815, -0.800768, 6.205148)],
    );
}

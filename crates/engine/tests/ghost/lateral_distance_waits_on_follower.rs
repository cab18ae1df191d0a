//! A LateralDistanceAction on a car driven by a FollowGhost controller stays with the car (the
//! ghost set-up hands it no such action) and idles: LatDistanceAction::Step returns while the
//! entity is in override mode on "DOMAIN_LAT", which is 1, the longitudinal domain's mask, and
//! ControllerFollowGhost is always in override mode. The engine moved the car sideways and
//! the follower then steered from the moved point. Found by a helper on s68068_00783.
//!
//! Fixture `lateral_distance_waits_on_ghost_follower.xosc` on difftest_straight.xodr: Car2
//! follows its ghost along y −8.75 and keeps that line while the action runs; esmini 3.6.0's
//! numbers (the engine: heading 6.2718 at 1.03 s).

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_action_idles_on_the_follower() {
    assert_fixture_matches_esmini("lateral_distance_waits_on_ghost_follower.xosc", 6.0, &[("Car2", 1.5, 35.0, -8.75, 0.0), ("Car2", 6.0, 80.0, -8.75, 0.0)]);
}

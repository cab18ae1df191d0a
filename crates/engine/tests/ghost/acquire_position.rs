//! An AcquirePositionAction on a FollowGhostController's entity moves to the ghost, as the
//! speed, lane change, trajectory, route and teleport actions do (ScenarioEngine::SetupGhost's
//! list includes ACQUIRE_POSITION): the ghost takes the route.
//!
//! Fixture `ghost_acquire_position.xosc` on fork.xodr: head start 1 s, the Ego's controller
//! never activated; the route to road 3 (the left branch) takes the ghost left at the fork,
//! while the Ego, without a route, drives straight on. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

const FIXTURE: &str = "ghost_acquire_position.xosc";

#[test]
fn an_acquire_position_action_routes_the_ghost_not_its_entity() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 8.0, 121.75, 40.832349, std::f64::consts::FRAC_PI_2);
    assert_esmini_pose_at(&run, "Ego", 8.0, 140.0, -1.75, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

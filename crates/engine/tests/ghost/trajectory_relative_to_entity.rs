//! A FollowTrajectoryAction handed over to the ghost whose polyline vertices are relative to
//! the ghost's own entity: esmini's FollowTrajectoryAction::ReplaceObjectRefs (called by
//! ScenarioEngine::SetupGhost; polyline vertices and a clothoid's start only) makes them
//! relative to the ghost.
//!
//! Fixture `ghost_trajectory_relative_to_entity.xosc` on straight.xodr: head start 1 s; at
//! 1.5 s (0.5 s for the ghost) the ghost follows a polyline from itself to 30 m ahead of it
//! in lane −2 — not from the Ego, 15 m behind. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

const FIXTURE: &str = "ghost_trajectory_relative_to_entity.xosc";

#[test]
fn a_ghosts_trajectory_relative_to_its_entity_is_relative_to_the_ghost() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 0.5, 52.5, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 0.51, 52.648989, -1.767382, 6.167044);
    assert_esmini_pose_at(&run, "Ego_ghost", 2.0, 74.848421, -4.357316, 6.167044);
    assert_esmini_pose_at(&run, "Ego", 6.0, 119.781999, -5.077225, 6.247928);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

//! A story action handed over to the ghost that names the ghost's entity as its reference: a
//! LaneChangeAction with a RelativeTargetLane on the entity itself. esmini's
//! ScenarioEngine::SetupGhost calls OSCPrivateAction::ReplaceObjectRefs on every action it
//! moves to the ghost, which makes such a reference (a relative lane, lane offset or speed
//! target, a speed profile's entity) name the ghost.
//!
//! Fixture `ghost_relative_lane_reference.xosc` on straight.xodr: head start 1 s; the ghost
//! changes to lane −2 (event at 1 s), then "+1 relative to the Ego" (event at 2.5 s) takes it
//! back to lane −1 — from its own lane −2, not from the standing-by Ego's lane −1 (which
//! would be lane 1). Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

const FIXTURE: &str = "ghost_relative_lane_reference.xosc";

#[test]
fn a_relative_lane_target_naming_the_entity_names_its_ghost() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 1.0, 59.482783, -5.25, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 3.0, 88.965566, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 6.0, 133.965566, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego", 6.0, 120.0, -1.75, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

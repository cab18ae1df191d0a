//! A TeleportAction handed over to the ghost whose position is relative to the ghost's own
//! entity: esmini's TeleportAction::ReplaceObjectRefs (Position::ReplaceObjectRefs, called by
//! ScenarioEngine::SetupGhost) makes the position relative to the ghost.
//!
//! Fixture `ghost_teleport_relative_to_entity.xosc` on straight.xodr: head start 1 s; at 1.5 s
//! (0.5 s for the ghost) a RelativeObjectPosition 10 m ahead of the Ego puts the ghost 10 m
//! ahead of itself (62.5, not 47.5 m). Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

const FIXTURE: &str = "ghost_teleport_relative_to_entity.xosc";

#[test]
fn a_ghosts_teleport_relative_to_its_entity_is_relative_to_the_ghost() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 0.5, 52.5, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 0.51, 62.5, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 6.0, 144.85, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego", 6.0, 120.0, -1.75, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

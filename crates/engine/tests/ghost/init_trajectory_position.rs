//! A ghost's copy of an Init TeleportAction to a TrajectoryPosition (ScenarioEngine::SetupGhost
//! copies the Init's actions with their copy constructors): TeleportAction's copies its
//! Position with Position::Duplicate (CopyConfig, CopyLocation, CopyState), which leaves the
//! trajectory out, so Position::TeleportTo evaluates nothing and copies the location the
//! position had before any evaluation — the origin, heading 0, on no road. The ghost's first
//! move fails there and it stops; a FollowGhost follower steers towards it and brakes.
//!
//! Fixture `ghost_init_trajectory_position.xosc` on straight.xodr: the Ego put 20 m along a
//! polyline starting at x = 10 (s = 30 in lane −1), head start 1 s, position mode. Numbers
//! from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_init_trajectory_position.xosc";

#[test]
fn the_ghosts_copy_of_a_trajectory_position_puts_it_at_the_origin() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    // The entity itself is where the trajectory says; its ghost at the origin, stopped.
    assert_esmini_pose_at(&run, "Ego", -1.0, 30.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", -1.0, 0.0, 0.0, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 3.0, 0.0, 0.0, 0.0);
    assert!(at(&run, "Ego_ghost", 0.0).speed.abs() < 1e-12, "{}", at(&run, "Ego_ghost", 0.0).speed);
    assert_esmini_pose_at(&run, "Ego", 1.0, 39.828428, -0.497146, 0.290604);
    assert_esmini_pose_at(&run, "Ego", 6.0, 41.004980, -0.020493, 0.379351);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

//! FollowGhostController activated on the lateral domain only: esmini's default controller
//! moves the entity along its lane first (ScenarioEngine::defaultController: the longitudinal
//! domain is not overridden), ControllerFollowGhost::Step then searches the ghost's trail and
//! aims from that position and heading while its vehicle model drives on from its own pose.
//!
//! Fixture `ghost_position_lateral_only.xosc`: `ghost_position_lookahead_past_trail_end.xosc`
//! with `longitudinal="false"`. Numbers from esmini 3.6.0's run (osc2cr, which kept the default
//! controller off the Ego, was 10.5 m away at 9.5 s).

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_position_lateral_only.xosc";

#[test]
fn a_ghost_follower_active_laterally_only_aims_from_where_the_default_controller_moved_it() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego", 3.0, 76.317977, -1.940624, 6.279262);
    assert_esmini_pose_at(&run, "Ego", 5.0, 123.357182, -1.967273, 0.000024);
    assert_esmini_pose_at(&run, "Ego", 10.0, 272.93, -1.967021, 0.0);
    assert!(close(at(&run, "Ego", 3.0).speed, 17.929405, 1e-3), "{}", at(&run, "Ego", 3.0).speed);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

//! A ghost left at the origin on no road (its copy of an Init TrajectoryPosition teleport, see
//! `init_trajectory_position.rs`) that a story FollowTrajectoryAction puts back on the road:
//! the trajectory sets its position from world coordinates (Position::XYZ2TrackPos), which
//! gives the position a road again, so once the trajectory ends esmini's default controller
//! (ScenarioEngine::defaultController, MoveAlongS) drives it on at its speed instead of
//! failing as on no road and stopping it.
//!
//! Fixture `ghost_back_on_road.xosc` on straight.xodr: head start 1 s; the trajectory runs from
//! x = 40 to 60 between absolute times 2 and 3 (the ghost reads them one head start early);
//! the Ego's controller is activated at 4 s. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_back_on_road.xosc";

#[test]
fn a_ghost_put_back_on_the_road_by_a_trajectory_drives_on_after_it() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 1.0, 0.0, 0.0, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 2.0, 60.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 3.0, 80.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego_ghost", 6.0, 140.0, -1.75, 0.0);
    assert!(close(at(&run, "Ego_ghost", 6.0).speed, 20.0, 1e-9), "{}", at(&run, "Ego_ghost", 6.0).speed);
    assert_esmini_pose_at(&run, "Ego", 5.0, 108.730162, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego", 6.0, 128.73, -1.75, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

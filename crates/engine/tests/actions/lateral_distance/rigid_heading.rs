//! A LateralDistanceAction in road coordinates without limits (esmini's MOVE_RIGID) turns the
//! entity along its jump: LatDistanceAction::Step sets the heading to atan2 of the displacement
//! since its last step, an absolute heading whose angle to the road the default controller's
//! move (Position::MoveAlongS, relative heading kept) carries through that step. So the row of
//! the jump faces along it, and a lateral SpeedCondition sees (almost) no sideways speed.
//!
//! Fixture `lat_distance_rigid_heading.xosc` on straight.xodr: the Ego (lane -2, 10 m/s) is
//! told at 1 s to keep 3 m left of the Target (lane -2): it jumps 3 m to the left in the step
//! to 1.03 s; an event that slows it down when its lateral speed exceeds 20 m/s never starts.
//! The numbers are esmini 3.6.0's run; where esmini runs here the whole run is compared.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn a_rigid_jump_faces_along_the_jump_and_shows_no_lateral_speed() {
    let run = run_fixture_scenario("lat_distance_rigid_heading.xosc", 10.0);
    // The jump: 3 m left while the default controller moves 0.1 m on, atan2(3, 0.1).
    assert_esmini_pose_at(&run, "Ego", 1.03, 50.3, -2.25, 1.537475);
    // The next step finds no error: the heading follows the default move again, and the
    // non-continuous action ends.
    assert_esmini_pose_at(&run, "Ego", 1.04, 50.4, -2.25, 0.0);
    assert_eq!(event_time(&run, "Slow", "start"), None, "the lateral SpeedCondition must not see the jump");
    assert!(close(at(&run, "Ego", 3.0).speed, 10.0, 1e-9), "{}", at(&run, "Ego", 3.0).speed);
    assert_matches_esmini("lat_distance_rigid_heading.xosc", &run, 1e-3);
}

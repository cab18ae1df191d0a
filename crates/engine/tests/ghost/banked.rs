//! A FollowGhostController steers from the heading the entity's position holds
//! (ControllerFollowGhost::Step: object_->pos_.GetH()), not from its vehicle model's own: on a
//! banked road SetInertiaPos turns the model's heading by the road's rotation, so the two
//! differ. Fixture `follow_ghost_banked.xosc` on banked.xodr (roll 0.01 rad/m): Ego at s = 100
//! with a ghost 1 s ahead at 10 m/s. Steering from the model's heading drifted 0.09 m left
//! within 2 s; esmini 3.6.0 keeps Ego at y −0.7296 there.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

const FIXTURE: &str = "follow_ghost_banked.xosc";

#[test]
fn a_ghost_follower_on_a_banked_road_steers_from_its_positions_heading() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego", 2.0, 119.998804, -0.729574, 0.023904);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

//! A LongitudinalDistanceAction without dynamics moves its actor by the whole distance error
//! in one step with esmini's `Position::MoveAlongS(ds)`, whose junction selector angle is −1:
//! without a route, Position::MoveToConnectingRoad draws the junction arm from the seeded
//! generator (GetNumberBetween over the lane's connections), it does not take the straightest.
//!
//! Fixture `long_distance_rigid_junction.xosc` on crossing.xodr: the Lead stands on the west
//! arm (road 3, s = 100); the Follower drives south on the south arm (road 4, lane −1, s = 50)
//! and at 1 s is told to trail the Lead by 10 m: the error is negative and it goes backwards
//! through the junction by it. esmini 3.6.0 (seed 0) draws the straight arm: the Follower lands
//! on the north arm at (−1.75, 121.42). (In the step after, esmini measures the Lead ahead
//! across the junction and our road-path distance does not yet agree, so only the drawn move
//! is asserted.)

use crate::common::oracle::{assert_esmini_pose_at, run_fixture_scenario};

#[test]
fn a_rigid_longitudinal_distance_draws_the_junction_arm() {
    let run = run_fixture_scenario("long_distance_rigid_junction.xosc", 5.0);
    assert_esmini_pose_at(&run, "Follower", 1.01, -1.75, -80.1, 4.71239);
    assert_esmini_pose_at(&run, "Follower", 1.02, -1.75, 121.415927, 4.71239);
}

//! An ACC car in override mode stopped at a dead end is not held there once a trajectory has
//! moved it away. esmini's ScenarioEngine::step zeroes the speed of an entity whose position
//! status says end of road and that did not move, reading the status its position has now:
//! a FollowTrajectoryAction that placed the entity in this step (SetInertiaPos → XYZ2TrackPos)
//! set it afresh, away from the end. The engine read the ACC's own status from its last move
//! and stopped the car each step. Found by crates/difftest (s57057_00723).
//!
//! Fixture `acc_at_road_end_then_trajectory.xosc` on straight.xodr: Cruiser (ACC, override,
//! 10 m/s) runs into the end of the road at s 1000 and stops; after 3 s a timed polyline puts
//! it back at x 975 and the ACC, taking the trajectory's first speed as its set speed,
//! accelerates (3.44 m/s at 3.5 s) — before, its speed decayed towards 0. esmini 3.6.0's
//! numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_trajectory_moves_an_acc_car_away_from_the_road_end_that_held_it() {
    assert_fixture_matches_esmini(
        "acc_at_road_end_then_trajectory.xosc",
        4.5,
        &[
            ("Cruiser", 2.0, 1000.0, -1.75, 0.0),
            ("Cruiser", 3.02, 975.100835, -1.75, 0.0),
            ("Cruiser", 3.5, 975.964095, -1.75, 0.0),
            ("Cruiser", 4.5, 982.889548, -1.75, 0.0),
        ],
    );
}

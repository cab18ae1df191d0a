//! The sign of a longitudinal distance along roads across a junction: esmini's
//! RoadPath::Calculate counts the other entity ahead when the path leaves the entity's road by
//! its end and the entity faces along s, or by its start and it faces against s. The engine
//! took the sign from a trial move along the roads, which follows the straightest arm and
//! missed a path that turns. Found by a helper on s64064_00613.
//!
//! Fixture `longitudinal_distance_across_junction_turn.xosc` on crossing.xodr: Car1 (road 4,
//! lane 1) keeps 7.66 m ahead of Car0 (road 3) from 1.39 s; the path leaves road 4 by its
//! start and turns through connecting road 111, so Car0 is ahead and Car1 is put at
//! (1.75, 205.13), not 525 m away at road 4's end. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_path_that_turns_through_a_junction_gives_the_sign_by_the_end_it_leaves() {
    assert_fixture_matches_esmini(
        "longitudinal_distance_across_junction_turn.xosc",
        8.79,
        &[("Car1", 1.40, 1.75, 205.129927, 1.570797), ("Car1", 3.0, -206.3888, -1.75, 0.0)],
    );
}

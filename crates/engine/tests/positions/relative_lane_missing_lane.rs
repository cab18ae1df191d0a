//! A RelativeLanePosition whose lane (the reference entity's lane plus `dLane`) does not exist
//! on the road the moved copy reached: esmini 3.6's Position::EvaluateRelation calls
//! SetLanePos, whose SetLanePosMode stores the asked offset first and then fails on the lane.
//! The position keeps the copy's lane id and world point (the copy's offset included: that is
//! where the entity is recorded at 0 s), but the default controller's first move goes on from
//! the lane and the asked offset, so the entity jumps to it.
//!
//! Fixture `relative_lane_missing_offset.xosc` on `tee_lht.xodr`: Car0 on road 1's lane −2 at
//! offset −1; Car1 60 m behind it along s, in the junction on road 100, which has no lane −2
//! (the copy is in lane 2 there); Car2 10 m ahead with dLane −2 (no lane −4). Both are recorded
//! at the copy's point at 0 s and at their lane's centre from the first step. The numbers are
//! esmini 3.6.0's run.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_relative_lane_position_on_a_missing_lane_moves_on_from_the_asked_offset() {
    assert_fixture_matches_esmini(
        "relative_lane_missing_offset.xosc",
        3.0,
        &[
            ("Car1", 0.0, 10.0, -6.25, std::f64::consts::PI),
            ("Car1", 0.01, 9.9, -5.25, std::f64::consts::PI),
            ("Car2", 0.0, 80.0, -6.25, 0.0),
            ("Car2", 0.01, 80.1, -5.25, 0.0),
            ("Car2", 2.0, 100.0, -5.25, 0.0),
        ],
    );
}

//! A LaneChangeAction relative to an entity esmini never placed: a RoutePosition
//! FromCurrentEntity is not implemented in esmini 3.6.0, so the entity keeps Position's
//! defaults (no road, lane 0, heading along s). LatLaneChangeAction::Start still reads it:
//! target lane 0 + value, and as esmini's SIGN(0) is +1, −1 becomes −2 (0 becomes 1). The
//! engine warned and did nothing. Found by a helper on s66066_00710.
//!
//! Fixture `lane_change_relative_to_unplaced_entity.xosc` on straight.xodr: Ego (lane −1)
//! changes lanes relative to Ref by −1 at 0.5 s over 2 s and ends in lane −2 (y −5.25 at
//! 3 s). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lane_change_relative_to_an_unplaced_entity_counts_from_lane_zero() {
    assert_fixture_matches_esmini(
        "lane_change_relative_to_unplaced_entity.xosc",
        3.0,
        &[("Ego", 1.5, 114.814103, -3.472512, 6.004852), ("Ego", 3.0, 129.61665, -5.25, 0.0)],
    );
}

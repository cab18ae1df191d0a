//! A road-frame LateralDistanceAction whose reference drives a lane that does not continue onto
//! the actor's road: Position::Delta carries the reference's lane along the road path to the
//! actor's road, GetConnectingLaneId answers 0 where the link has no lane link, and dt is
//! tB + tA, not tB − tA, whenever SIGN of the carried lane differs from SIGN of the reference's
//! lane, with SIGN(0) = +1. So a reference on a right lane (negative id) without a lane link
//! is measured as if across the reference line, and the actor goes the other way. The engine
//! compared the roads' directions only. Found by a helper on s73073_00031.
//!
//! Fixtures on two roads end to end: `lat_distance_reference_lane_unlinked.xosc` on
//! two_roads_lane_minus2_unlinked.xodr (lane −2 has no links), where esmini's actor moves left,
//! to (129.674, 1.371) at 2 s; `lat_distance_reference_lane_linked.xosc`, the same on
//! two_roads.xodr, where it moves right, to (129.954, −3.009). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn an_unlinked_reference_lane_adds_the_offsets() {
    assert_fixture_matches_esmini("lat_distance_reference_lane_unlinked.xosc", 2.0, &[("Actor", 2.0, 129.674144, 1.370871, 0.246209)]);
}

#[test]
fn a_linked_reference_lane_subtracts_them() {
    assert_fixture_matches_esmini("lat_distance_reference_lane_linked.xosc", 2.0, &[("Actor", 2.0, 129.954016, -3.008565, 6.213291)]);
}

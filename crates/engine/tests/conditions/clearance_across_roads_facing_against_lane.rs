//! A RelativeClearanceCondition (not free space) between entities on different roads signs the
//! distance as Position::Delta's road path does (RoadPath::Calculate: ahead when the path
//! leaves the entity's road by the end it faces, turned again when the entity's heading from
//! its lane's driving direction, taken in [−π, π], is above π/2: one side of "against" only),
//! as the road-frame distance conditions already did. The engine took the sign from which
//! side of the entity's heading the other lay. Found by a helper on s74074_00558.
//!
//! Fixture `clearance_across_roads_facing_against_lane.xosc` on two_roads.xodr: A1 and A2 on
//! road 1's lane 1 (which runs against +x), both facing +x, against their lane: A1 turned a
//! milliradian to the right, A2 a milliradian to the left; both look for B, 15 m ahead on
//! road 2. esmini: A1's distance is negative, outside the backward range, so its area is
//! clear and E1 starts F1 at once; A2's lies within the forward range, so E2 never starts F2.
//! esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_path_distance_is_signed_by_the_lane_direction() {
    assert_fixture_matches_esmini("clearance_across_roads_facing_against_lane.xosc", 0.5, &[("F1", 0.5, 50.5, -1.75, 0.0), ("F2", 0.5, 50.0, -5.25, 0.0)]);
}

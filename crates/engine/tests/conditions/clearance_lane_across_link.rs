//! A RelativeClearanceCondition's lane difference across roads: esmini's
//! Object::FreeSpaceDistanceObjectRoadLane reports the lane difference of its last corner pair
//! (the front right corners) from Position::Delta, which carries the first corner's lane along
//! the road path onto the second corner's road (Road::GetConnectingLaneId across the last
//! link) before subtracting. Comparing the raw lane ids made a car whose corner had entered a
//! junction connecting road that runs the other way look like it was in an opposite lane, out
//! of the range. Found by crates/difftest (s58058_00264 on lane_offset_intersection).
//!
//! Fixture `clearance_lane_across_link.xosc` on junction_reverse_link.xodr (a road ending in a
//! junction, with a connecting road leading back into its lane 1, whose lane -1 links to it):
//! Car1 drives the wrong way in lane 1 into the junction behind Car0; from 2.02 s its front
//! right corner lies on that connecting road in lane -1, which is lane 1 carried across the
//! link, so the clearance behind Car0 (40.33 m) stays taken until the gap passes it at 3.10 s
//! and Car0 only then speeds up. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_corner_on_a_connecting_road_keeps_the_lane_carried_across_the_link() {
    assert_fixture_matches_esmini(
        "clearance_lane_across_link.xosc",
        4.0,
        &[
            ("Car1", 2.05, 96.3, 1.75, 0.0),
            ("Car0", 3.10, 60.0, 1.75, std::f64::consts::PI),
            ("Car0", 3.11, 59.97, 1.75, std::f64::consts::PI),
            ("Car0", 4.0, 57.3, 1.75, std::f64::consts::PI),
        ],
    );
}

//! A junction lane link to a lane the connecting road lacks is still an arm: esmini's
//! Junction::GetRoadConnectionByIdx only logs that the target lane is not found. Entering it,
//! Position::SetLanePos fails after SetLongitudinalTrackPos switched the road (which reset the
//! lane id to 0), and the offset stays: the car drives the connecting road in lane 0, and at
//! its end takes the next road's closest lane. The engine dropped the arm and stopped the car
//! at the road's end. Found by a helper on s65065_00295 (highway_merge).
//!
//! Fixture `junction_lane_link_to_missing_lane.xosc` on junction_lane_link_to_missing_lane.xodr
//! (road 1, junction road 2 with lane −1 only, road 3; the one connection links lane −1 to −2):
//! the car (lane −1, offset 0.4) is at y 0.4 in lane 0 on road 2 at 1.5 s and in road 3's lane
//! 1 (y 1.75) at 3 s. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lane_link_to_a_missing_lane_is_driven_in_lane_zero() {
    assert_fixture_matches_esmini(
        "junction_lane_link_to_missing_lane.xosc",
        4.0,
        &[("Ego", 1.5, 55.0, 0.4, 0.0), ("Ego", 3.0, 70.0, 1.75, 0.0), ("Ego", 4.0, 80.0, 1.75, 0.0)],
    );
}

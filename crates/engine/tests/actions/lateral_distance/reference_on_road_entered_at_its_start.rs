//! Position::Delta carries a lane across the path's last road from the end the path leaves
//! the road before it by (last_node->contactPoint), not from the end it enters the other road
//! by: from a connecting road whose start follows the incoming road's end, the lane is carried
//! from the incoming road's start. Where the linked lane only begins later on that road, the
//! carried lane is 0, whose sign differs, and dt becomes tB + tA. The engine carried the lane
//! from the end the path really enters by. Found by a helper on s77077_00771.
//!
//! Fixture `lateral_distance_reference_on_road_entered_at_its_start.xosc` on a map of ours,
//! lane_added_before_junction.xodr (road 0 gains lane -4 at s 50, and connecting road 4 leaves
//! its end from lane -4): Ego on road 0 keeps 4 m right of Ref on road 4. esmini 3.6.0's
//! numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_lane_is_carried_from_the_start() {
    assert_fixture_matches_esmini(
        "lateral_distance_reference_on_road_entered_at_its_start.xosc",
        2.0,
        &[("Ego", 0.01, 180.05, -8.75, 0.0), ("Ego", 0.22, 181.1, 5.75, 1.567348), ("Ego", 1.5, 187.5, 5.75, std::f64::consts::TAU)],
    );
}

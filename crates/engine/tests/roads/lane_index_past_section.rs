//! A move past a road's end from an earlier lane section continues the lane at the index the
//! entity's lane had there: esmini's Position::MoveAlongS switches to the end's lane section
//! without updating the lane index (lanes sorted by id, the most positive first, the centre
//! lane among them), and MoveToConnectingRoad continues the lane at that index of the end
//! section. Where that is the centre lane it has no link ("trying move to closest lane": the
//! next road's lane nearest the old t); where the index is past the section's lanes there is no
//! connection and the move ends at the road's end. Found by a helper on s62062_00660 (a rigid
//! LongitudinalDistanceAction on a map whose lane sections differ in left lanes).
//!
//! Fixture `relative_road_position_keeps_lane_index.xosc` on left_lane_drops.xodr (road 1 with
//! two left lanes up to s 50 and one after, then road 2): cars at s 30 of road 1 and
//! RelativeRoadPositions 90 m on from them. From lane -1 (index 3) the move goes on in lane -2;
//! from lane 2 (index 0) in lane 1; from lane 1 (index 1, the centre lane in the last section)
//! in the lane nearest its t, lane 1; from lane -2 (index 4, none) it stays at road 1's end.
//! esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_move_past_the_road_end_keeps_the_lane_index_of_the_section_it_started_in() {
    assert_fixture_matches_esmini(
        "relative_road_position_keeps_lane_index.xosc",
        0.1,
        &[("B", 0.0, 120.0, -5.25, 0.0), ("D", 0.0, 120.0, 1.75, 0.0), ("F", 0.0, 120.0, 1.75, 0.0), ("H", 0.0, 100.0, -5.25, 0.0)],
    );
}

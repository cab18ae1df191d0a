//! A free-space RelativeClearanceCondition measures corners on other roads than the entity's
//! along the road path, as esmini's Object::FreeSpaceDistanceObjectRoadLane does for every
//! pair of entities, whichever roads they are on: each corner located from the entity's
//! position (XYZ2TrackPos), sixteen Position::Delta, and a gap of 0 where one corner's deltas
//! disagree in sign — as they do while the box straddles its road's end. Found by
//! crates/difftest (s36036_00294 on simple_3way_motorway, s35035_00350 on
//! simple_4way_intersection); before, entities on two roads were compared centre to centre.
//!
//! Fixture `relative_clearance_corners_across_road_end.xosc` on crossing.xodr: Driver comes
//! down the north arm (road 2, lane 1) into the junction at 22 m/s; Far stands on the west arm
//! 35 m from the centre. The window (34.09 m forward, 10.64 m back) is clear until Driver's
//! reference point crosses its road's end at 0.55 s: the clearance falls and Slow sets 5 m/s.
//! Without the rule the clearance never fell. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_box_straddling_its_road_end_has_no_clearance() {
    let run = assert_fixture_matches_esmini(
        "relative_clearance_corners_across_road_end.xosc",
        5.0,
        &[("Driver", 0.5, -1.75, 21.0, 4.71239), ("Driver", 0.6, -1.75, 19.65, 4.71239), ("Driver", 5.0, -1.75, -2.35, 4.71239)],
    );
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
}

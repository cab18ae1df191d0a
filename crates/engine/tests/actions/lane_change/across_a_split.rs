//! A lane change without a route still going on when its entity passes into a direct junction
//! over the arm beside the one its target lane leads to: esmini's LatLaneChangeAction::Step
//! moves the internal position along the target lane (road 1's lane -1 into road 2), then
//! XYZ2TrackPos attaches the entity to the road its point is on, road 3, since the point lies
//! more than 2 m beside road 2 (the current road's hold) and road 3 contains it. The motion
//! still follows road 2; the next lateral action starts from road 3's lane.
//!
//! Fixture `lane_change_across_a_split.xosc` on `direct_split.xodr`: Changer, at the outer edge
//! of lane -2, changes to lane -1 over 400 m; a lane offset of 0 at 5.2 s ends the change and
//! takes it to the centre of road 3's lane, which bends right. Before, the engine kept it on
//! road 2 (y -1.75 at the end, 50 m from esmini). Keeper changes the same way without the
//! offset and goes on along road 2. The numbers are esmini 3.6.0's run.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lane_change_over_the_other_arm_of_a_split_attaches_to_it() {
    assert_fixture_matches_esmini(
        "lane_change_across_a_split.xosc",
        15.0,
        &[
            ("Changer", 9.0, 139.13438, -13.380286, 5.873507),
            ("Changer", 15.0, 183.738394, -52.109886, 5.26282),
            ("Keeper", 15.0, 179.99381, -5.878344, 0.016509),
        ],
    );
}

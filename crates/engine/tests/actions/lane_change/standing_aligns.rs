//! A lane change turns its entity to the road's direction when it starts, even standing still:
//! LatLaneChangeAction::Start "aligns to road" with Position::SetHeadingRelativeRoadDirection(0),
//! which evaluates the heading at once (EvaluateHPR), keeping the way the entity faced along
//! the road; its Step then returns early while the speed is 0, so nothing else turns it. Found
//! by crates/difftest (s57057_00781: a car stopped at a road end, askew).
//!
//! Fixture `lane_change_standing_aligns.xosc` on straight.xodr: Askew stands on lane −1 facing
//! 0.3 rad off the road; at 0.5 s a lane change to lane −2 starts, and its heading is 0 from
//! the next step, while it has not moved; from 1 s it drives at 10 m/s and changes lanes.
//! Before the rule it stood at 0.3 rad until it moved. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lane_change_turns_a_standing_entity_to_the_road_at_once() {
    assert_fixture_matches_esmini(
        "lane_change_standing_aligns.xosc",
        5.0,
        &[
            ("Askew", 0.5, 100.0, -1.75, 0.3),
            ("Askew", 0.52, 100.0, -1.75, 0.0),
            ("Askew", 2.0, 109.852439, -2.609178, 6.125782),
            ("Askew", 5.0, 139.646511, -5.25, 0.0),
        ],
    );
}

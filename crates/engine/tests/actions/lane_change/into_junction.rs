//! A lane change still going on when its entity enters a junction: esmini's
//! LatLaneChangeAction::Step moves the entity with Position::MoveAlongS and junction selector
//! angle −1, so without a route Position::MoveToConnectingRoad draws the arm from its seeded
//! generator (`GetNumberBetween(0, n − 1)` over the lane's connections in the junction's
//! order), straight on or not — the default controller's rule (the straightest arm) does not
//! apply.
//!
//! Fixture `lane_change_junction_draw.xosc` on `tee_lht.xodr` (difftest's left-hand-traffic
//! T): Car0 changes from lane −2 to −1 on road 1 and enters the junction mid-change; its
//! lane's connections are the straight road 100, then the left turn 101, and esmini's first
//! draw (seed 0) takes the left turn. Car1 does the same from road 3 (right turn 104, left
//! turn 105): the second draw takes 105. The numbers are esmini 3.6.0's run.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lane_change_into_a_junction_takes_the_arm_esmini_draws() {
    assert_fixture_matches_esmini(
        "lane_change_junction_draw.xosc",
        8.0,
        &[
            // In the left turn, not on the straight road 100 (y stays −3.5 there).
            ("Car0", 3.5, 15.096492, -3.780958, 3.346318),
            ("Car0", 7.0, 1.75, -32.307264, 4.71239),
            ("Car1", 7.0, -19.442722, -1.75851, 3.111052),
        ],
    );
}

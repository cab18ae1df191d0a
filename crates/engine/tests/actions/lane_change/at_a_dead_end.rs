//! A lane change started by an entity standing at a road's dead end (an end without a link
//! element) ends in its first step: LatLaneChangeAction::Step ends the action on
//! POS_STATUS_END_OF_ROAD, which Position::MoveAlongS leaves after every move that stays within
//! SMALL_NUMBER of such an end, one too short to go anywhere included (with a route), and
//! XYZ2TrackPos's re-attachment leaves there too (without a route). Fixture
//! `lane_change_at_a_dead_end.xosc` on straight.xodr: Routed (with a route) and Free (without)
//! reach the two ends of the road at 1 s, still at 10 m/s, and start a lane change of 0.2 s,
//! too fast sideways for the speed: the step goes nowhere along the road. esmini 3.6.0 ends
//! both at 1 s, after one step sideways (Routed 2 cm).

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "lane_change_at_a_dead_end.xosc";

#[test]
fn a_lane_change_at_a_dead_end_ends_at_once() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    for action in ["LRouted", "LFree"] {
        let end = run.trace.events.iter().find(|ev| ev.element == action && ev.to == "complete").map(|ev| ev.time);
        assert!(end.is_some_and(|t| close(t, 1.0, 1e-9)), "{action} ends at {end:?}");
    }
    assert!(close(at(&run, "Routed", 2.0).y, -1.7715, 1e-4), "{:?}", at(&run, "Routed", 2.0));
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

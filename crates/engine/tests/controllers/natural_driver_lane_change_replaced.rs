//! A NaturalDriver's new lane change replaces one still running: the driver injects the next
//! as soon as its cooldown (laneChangeDuration and the delay) runs out, and
//! PlayerServer::AddAction ends any listed action of the same type for the same object
//! ("already ongoing …, stopping it") before listing the new one. A slow lane change (the
//! linear fallback at low speed) outlasts the cooldown. The engine refused the injection
//! while a change ran. Found by a helper on s74074_00845.
//!
//! Fixture `natural_driver_lane_change_replaced.xosc` on divided_two_lanes.xodr: Car0, a
//! NaturalDriver at 6 m/s between two other cars; esmini stops LaneChangeAction_0 and starts
//! LaneChangeAction_1 at 5.97 s (Car0 at x 592.260, heading π at 5.98 s, where the first
//! change had it at 3.311). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_running_change_is_stopped() {
    assert_fixture_matches_esmini(
        "natural_driver_lane_change_replaced.xosc",
        8.0,
        &[("Car0", 5.98, 592.259573, 5.390319, std::f64::consts::PI), ("Car0", 7.0, 586.187076, 5.699837, 3.045032)],
    );
}

//! The lane change a FollowRouteController creates aligns its car with the road in the step it
//! is created (ControllerFollowRoute::ChangeLane calls LatLaneChangeAction::Start, which sets
//! the relative heading 0 at once), and puts the car on the target lane only from its first
//! step at speed: until then the controller plans from the car's own lane. The engine
//! aligned one step later and planned from the target lane at once. Found by a helper on
//! s73073_00125.
//!
//! Fixture `follow_route_lane_change_aligns_at_start.xosc` on two_roads.xodr: Ego on lane −1
//! turned 0.3 rad from it, its route on lane −2: esmini's heading is 0 from the first row.
//! esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_change_aligns_the_car_in_its_first_step() {
    assert_fixture_matches_esmini(
        "follow_route_lane_change_aligns_at_start.xosc",
        5.0,
        &[("Ego", 0.0, 10.0, -1.75, 0.0), ("Ego", 0.01, 10.1, -1.750096, 0.0), ("Ego", 2.0, 29.796591, -4.375, 6.122841)],
    );
}

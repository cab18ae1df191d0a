//! Route waypoints given in the world, as esmini 3.6 takes them: every waypoint is attached to
//! a road (Position::SetInertiaPos → XYZ2TrackPos; the lane of the driving types containing the
//! point, else the nearest one), so a route through a WorldPosition plans like one through a
//! LanePosition (it could not be planned: "waypoint 1 is not on a lane"). Fixture
//! `route_world_waypoints.xosc` (fork.xodr: a road that forks straight on and left): routes
//! assigned with a world waypoint on the left arm (one given wholly in the world, with
//! headings; one whose waypoint lies beside the lane), an AcquirePositionAction to a world
//! point, a RoutePosition on such a route, and a car without a route. The numbers are esmini
//! 3.6.0's run of it; where esmini runs here the whole run is compared too.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use std::f64::consts::FRAC_PI_2;

#[test]
fn routes_through_world_waypoints_turn_where_esmini_turns() {
    let run = run_fixture_scenario("route_world_waypoints.xosc", 20.0);
    assert_esmini_pose_at(&run, "Assigned", 14.0, 121.75, 45.84, FRAC_PI_2);
    assert_esmini_pose_at(&run, "WorldOnly", 14.0, 121.75, 65.84, FRAC_PI_2);
    assert_esmini_pose_at(&run, "OffCentre", 14.0, 121.75, 25.84, FRAC_PI_2);
    assert_esmini_pose_at(&run, "Acquire", 14.0, 121.75, 35.84, FRAC_PI_2);
    // A RoutePosition places the entity without assigning the route; without a route the
    // straightest arm.
    assert_esmini_pose_at(&run, "Placed", 14.0, 210.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Free", 14.0, 170.0, -1.75, 0.0);
    assert_matches_esmini("route_world_waypoints.xosc", &run, 1e-3);
}

//! A FollowRouteController whose narrowed route pairs two roads not linked directly stops its
//! car for good: Route::ReplaceMinimalWaypoints (from ControllerFollowRoute::UpdateWaypoints /
//! CalculateWaypoints) gives the first waypoint a direction only when it is on the second's
//! road or links to it (Route::CalculcateWPDirWrtWP: Road::IsPredecessor / IsSuccessor);
//! without one ("Invalid waypoint …, can't find direction") every Route::SetPathS fails
//! ("Unexpected lack of connection in route"), Position::MoveAlongS returns before moving and
//! ScenarioEngine::defaultController sets the speed to 0. It happens to a car facing along s in
//! a lane that drives against s: the controller's path follows the heading, the route the
//! lane. The engine planned a full route between the pair. Found by a helper on s73073_00889.
//!
//! Fixture `follow_route_waypoints_not_linked.xosc` on ring.xodr (roads 0 → 1 → 2 → 3 → 0):
//! Car0 on road 0's lane 1 facing +s at 7.01 m/s, its route along lane 1 to road 2 the other
//! way round; the controller pairs road 0 with road 2. esmini moves it one step, to x 59.3901,
//! and stops it there. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_car_stops_after_one_step() {
    let run =
        assert_fixture_matches_esmini("follow_route_waypoints_not_linked.xosc", 2.0, &[("Car0", 0.02, 59.3901, 1.75, 0.0), ("Car0", 2.0, 59.3901, 1.75, 0.0)]);
    assert_eq!(crate::common::at(&run, "Car0", 2.0).speed, 0.0);
}

//! An AssignRouteAction whose route esmini cannot plan still replaces the route the entity
//! had: Route::AddWaypoint marks a route with no way between two of its waypoints invalid,
//! Route::CheckValid drops its waypoints, and AssignRouteAction::Start gives the entity that
//! empty route, so it drives on as without one. The engine warned and kept the old route.
//! Found by a helper on s68068_00564.
//!
//! Fixture `assign_invalid_route_drops_the_old_one.xosc` on fork.xodr: the car gets a route
//! turning left at the fork (road 1 to road 3), then at 1 s one that cannot be planned (road 2
//! back to road 1 against the one-way fork). esmini's car goes straight on: (120, −1.75) at
//! 6 s, where the old route had it at (117.30, 6.82) on the left arm. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn an_unplannable_route_replaces_the_old_one() {
    assert_fixture_matches_esmini("assign_invalid_route_drops_the_old_one.xosc", 8.0, &[("Car", 6.0, 120.0, -1.75, 0.0)]);
}

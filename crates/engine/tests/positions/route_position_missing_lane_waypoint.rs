//! A RoutePosition on a route whose waypoints are LanePositions on a lane the road does not
//! have there. esmini 3.6's Position::SetLanePosMode sets road and s (SetLongitudinalTrackPos)
//! before it finds the lane missing ("Lane id -3 does not exist"), so Route::AddWaypoint keeps
//! each waypoint at its road and s with lane id 0; a pathS beyond the route's length leaves the
//! route at its first waypoint (Route::SetPathS returns before moving it), and the position is
//! that road and s on the RoutePosition's own lane. Before, the engine gave up on the route and
//! left the entity at the world origin.
//!
//! Fixture `route_position_missing_lane_waypoint.xosc` on straight.xodr (lanes 1, −1, −2): two
//! waypoints on lane −3 at s = 100 and 130, pathS 50, lane −1, offset 0.3; the numbers are
//! esmini 3.6.0's run of it (at 0 s (100, −1.45), at 3.01 s (130.1, −1.45)); where esmini runs
//! here the whole run is compared.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn a_route_on_a_missing_lane_places_at_its_first_waypoint() {
    let run = run_fixture_scenario("route_position_missing_lane_waypoint.xosc", 10.0);
    assert_esmini_poses(&run, &[("Ego", 0.0, 100.0, -1.45, 0.0), ("Ego", 3.01, 130.1, -1.45, 0.0)], 1e-6, 1e-9);
    assert_matches_esmini("route_position_missing_lane_waypoint.xosc", &run, 1e-3);
}

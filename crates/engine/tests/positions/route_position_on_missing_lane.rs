//! A RoutePosition whose own lane the road does not have at the route's s. esmini 3.6's
//! Position::SetLanePosMode (from Position::SetRouteLanePosition) sets road, s and the offset
//! (SetLongitudinalTrackPos) before it finds the lane missing and returns without Track2XYZ:
//! the entity is recorded at the world origin, its lane id stays 0, and the default controller
//! moves it on from those road coordinates (s, t = the offset). Before, the engine moved it on
//! from the origin. Found by crates/difftest (hold5 seed_13013_maps/s13013_00984: the same on
//! a route whose waypoints are on a missing lane, with an ACC controller that re-places the
//! entity on the first step).
//!
//! Fixture `route_position_on_missing_lane.xosc` on straight.xodr (lanes 1, −1, −2): Ego's
//! waypoints are on lane −3 (kept at s 100 and 130, lane 0), pathS 50 lies beyond the route,
//! lane −5, offset 0.3; Back's on lane −1, pathS 10, lane 5 (facing −s), offset 0.3. The
//! numbers are esmini 3.6.0's run of it.

use crate::common::*;

#[test]
fn a_route_position_on_a_missing_lane_moves_on_from_its_road_coordinates() {
    let run = run_fixture_on("route_position_on_missing_lane.xosc", "straight.xodr", 3.0);
    let rows = [
        ("Ego", 0.0, 0.0, 0.0, 0.0),
        ("Back", 0.0, 0.0, 0.0, std::f64::consts::PI),
        ("Ego", 0.01, 100.1, 0.3, 0.0),
        ("Back", 0.01, 109.9, 0.3, std::f64::consts::PI),
        ("Ego", 2.0, 120.0, 0.3, 0.0),
        ("Back", 2.0, 90.0, 0.3, std::f64::consts::PI),
    ];
    assert_esmini_poses(&run, &rows, 1e-6, 1e-6);
}

//! A RoutePosition's pathS counted as esmini counts it on a route whose waypoints esmini
//! drops (Route::AddWaypoint drops an anchor when the next waypoint shares its road, then
//! measures the route s of the anchor it puts on each road passed from the dropped waypoint;
//! Route::SetPathS counts a path s from the last anchor before it). Found by crates/difftest
//! (m4004/s4004_00294, m6006/s6006_00031, m6006/s6006_00146). Fixture
//! `route_position_dropped_waypoints.xosc` on `three_roads.xodr` (roads 0, 1, 2 of 50 m in a
//! row along +x): Ego's route has waypoints at s 5, 20, 40 of road 0 and s 30 of road 2, so
//! the anchor on road 1 (s 16.5, 61.5 m along) gets route s 26.5 (measured from s 40) and
//! pathS 30 lands 3.5 m past it, on road 1 at s 20; Ahead's route (s 5 of road 0, s 30 of
//! road 2) has no dropped waypoint and its pathS 30 is road 0 at s 35. Expected values:
//! esmini 3.6.0 on the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 2] = [(0.0, 70.0, -1.75, 10.0), (2.0, 90.0, -1.75, 10.0)];
const AHEAD: [(f64, f64, f64, f64); 2] = [(0.0, 35.0, -1.75, 5.0), (2.0, 45.0, -1.75, 5.0)];

#[test]
fn path_s_counts_from_the_anchors_esmini_keeps() {
    let run = run_fixture_on("route_position_dropped_waypoints.xosc", "three_roads.xodr", 2.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-6);
    assert_esmini_rows(&run, "Ahead", &AHEAD, 1e-6);
}

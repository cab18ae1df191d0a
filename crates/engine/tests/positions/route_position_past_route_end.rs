//! A RoutePosition's pathS that esmini's anchors carry beyond the route's last waypoint. After
//! a dropped waypoint the anchors count short (see `route_position_dropped_waypoints.rs`), so a
//! path s within esmini's route length can land beyond the planned route's end; Route::SetPathS
//! then goes on from where the route enters the last road by what is left, and
//! Position::SetLanePos holds s within that road ("Unexpected: local_s … out of range"): past
//! the last waypoint, up to the road's end. Found by crates/difftest (s31031_00113 on
//! fabriksgatan_traffic_lights.xodr). Fixture `route_position_past_route_end.xosc` on
//! `three_roads.xodr` (roads 0, 1, 2 of 50 m in a row along +x): both routes have waypoints at s
//! 5 and 40 of road 0 and s 30 of road 2, so the anchor on road 1 (s 16.5) gets route s 26.5
//! and the last waypoint 125. Ego's pathS 100 is 73.5 m past the anchor: road 2 at s 40, 10 m
//! past the last waypoint; Ahead's pathS 120 would be s 60, held at the road's end (s 50).
//! Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 3] = [(0.0, 140.0, -1.75, 10.0), (1.0, 150.0, -1.75, 10.0), (2.0, 150.0, -1.75, 0.0)];
const AHEAD: [(f64, f64, f64, f64); 2] = [(0.0, 150.0, -1.75, 10.0), (1.0, 150.0, -1.75, 0.0)];

#[test]
fn a_path_s_past_the_last_waypoint_goes_on_along_the_last_road_up_to_its_end() {
    let run = run_fixture_on("route_position_past_route_end.xosc", "three_roads.xodr", 2.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-6);
    assert_esmini_rows(&run, "Ahead", &AHEAD, 1e-6);
}

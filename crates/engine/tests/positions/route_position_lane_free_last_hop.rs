//! A route whose last road is reached only by a road end that the lane driven does not
//! continue into. esmini plans a route road by road (Route::AddWaypoint → RoadPath::Calculate):
//! a linked road or a junction's connecting road that is the target road counts as reached
//! before RoadPath::CheckRoad looks at lanes, so the route exists and a RoutePosition along it
//! is placed; a lane-by-lane search finds no way. Found by crates/difftest (s32032_00109 on the
//! generated left-hand-traffic T junction). Fixture `route_position_lane_free_last_hop.xosc` on
//! `tee_lht.xodr`: the route runs from lane -2 of road 2 (left-hand traffic: against s, towards
//! the junction) to lane 2 of connecting road 100, which joins road 2's start only with its
//! lanes 1 and 2. OnConnector's pathS 40 is 10 m into road 100 from its end (s 30);
//! BeforeJunction's pathS 12 is s 18 of road 2. Before the rule both were left at the route's
//! first waypoint (s 30 of road 2), 40 m and 12 m from esmini. Expected values: esmini 3.6.0 on
//! the fixture.

use crate::common::*;

const ON_CONNECTOR: [(f64, f64, f64, f64); 2] = [(0.0, -10.0, -5.25, 5.0), (2.0, 0.0, -5.25, 5.0)];
const BEFORE_JUNCTION: [(f64, f64, f64, f64); 2] = [(0.0, -38.0, 5.0, 5.0), (2.0, -48.0, 5.0, 5.0)];

#[test]
fn a_route_enters_its_last_road_from_a_lane_that_does_not_continue_into_it() {
    let run = run_fixture_on("route_position_lane_free_last_hop.xosc", "tee_lht.xodr", 2.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_rows(&run, "OnConnector", &ON_CONNECTOR, 1e-6);
    assert_esmini_rows(&run, "BeforeJunction", &BEFORE_JUNCTION, 1e-6);
}

//! RoutePosition, AssignRouteAction and AcquirePositionAction on the straight fixture road
//! (one road along +x; lanes −1 and −2 drive along +s, lane 1 against), and one on the crossing.

use crate::common::oracle::{assert_esmini_pose_at, run_fixture_scenario};
use crate::common::*;

fn lane(s: f64, lane: i32) -> String {
    format!(r#"<Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/></Position>"#)
}

fn route(waypoints: &[(f64, i32)]) -> String {
    let w: String = waypoints.iter().map(|(s, l)| format!(r#"<Waypoint routeStrategy="shortest">{}</Waypoint>"#, lane(*s, *l))).collect();
    format!(r#"<Route name="R" closed="false"><ParameterDeclarations/>{w}</Route>"#)
}

fn route_position(route: &str, in_route: &str) -> String {
    format!(r#"<Position><RoutePosition><RouteRef>{route}</RouteRef><InRoutePosition>{in_route}</InRoutePosition></RoutePosition></Position>"#)
}

#[test]
fn route_position_in_lane_coordinates() {
    // The route starts at s = 10 on lane −1: path s 100 is road s 110; lane −2's centre is y = −5.25.
    let r = route(&[(10.0, -1), (500.0, -1)]);
    let pos = route_position(&r, r#"<FromLaneCoordinates pathS="100" laneId="-2" laneOffset="0.5"/>"#);
    let init = format!(r#"<Private entityRef="Ego"><PrivateAction><TeleportAction>{pos}</TeleportAction></PrivateAction></Private>"#);
    let run = run(&xosc(&init, "", &stop_at(1.0)));
    let e = at(&run, "Ego", 0.0);
    assert!(close(e.x, 110.0, 1e-9) && close(e.y, -5.25 + 0.5, 1e-9) && close(e.h, 0.0, 1e-9), "{e:?}");
}

#[test]
fn route_position_against_s_faces_the_road_direction_and_reads_t_as_an_integer() {
    // Lane 1 drives against s: a route from s = 500 to s = 100 on it; path s 50 is road s 450.
    // esmini 3.6.0 (OSCPositionRoute::SetRouteRefRoadCoord, ScenarioReader's strtoi of t) puts
    // it at t = 1, not 1.75, facing the road's reference direction, not the route's.
    let r = route(&[(500.0, 1), (100.0, 1)]);
    let pos = route_position(&r, r#"<FromRoadCoordinates pathS="50" t="1.75"/>"#);
    let init = format!(r#"<Private entityRef="Ego"><PrivateAction><TeleportAction>{pos}</TeleportAction></PrivateAction></Private>"#);
    let run = run(&xosc(&init, "", &stop_at(1.0)));
    let e = at(&run, "Ego", 0.0);
    assert!(close(e.x, 450.0, 1e-9) && close(e.y, 1.0, 1e-9) && close(e.h, 0.0, 1e-9), "{e:?}");
}

#[test]
fn assign_route_and_acquire_position_complete_at_once_and_warn_about_nothing() {
    let r = route(&[(10.0, -1), (500.0, -1)]);
    let assign = format!(r#"<PrivateAction><RoutingAction><AssignRouteAction>{r}</AssignRouteAction></RoutingAction></PrivateAction>"#);
    let acquire =
        format!(r#"<PrivateAction><RoutingAction><AcquirePositionAction>{}</AcquirePositionAction></RoutingAction></PrivateAction>"#, lane(300.0, -1));
    let init = format!(r#"{}<Private entityRef="Ego">{assign}{}</Private>"#, teleport("Ego", 10.0, -1), speed_action("step", "time", 0.0, 10.0));
    let stories = story("Ego", &event("Acquire", "overwrite", &acquire, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let run = run(&xosc(&init, &stories, &stop_at(3.0)));
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_eq!(event_time(&run, "AcquireAction", "end"), event_time(&run, "AcquireAction", "start"));
    // The route changes nothing on a road without junctions: 10 m/s along the lane.
    assert!(close(at(&run, "Ego", 2.0).x, 30.0, 1e-9));
}

#[test]
fn acquire_position_behind_on_the_same_road_routes_along_that_road_alone() {
    // Fixture `acquire_position_behind_on_same_road.xosc` on crossing.xodr: Car drives west on
    // road 1 (lane 1, against s) towards the junction and at 0.5 s acquires a position behind
    // it on the same road (lane −1, s = 200). esmini's RoadPath::Calculate joins two waypoints
    // on one road by their s difference, so the route is valid and is road 1 alone: at the
    // junction Route::GetRoadAtOtherEndOfIncomingRoad finds no road and
    // Position::MoveToConnectingRoad takes the lane's first connection, the right turn north.
    // Other, on road 3 without a route, goes straight on. Poses are esmini 3.6.0's.
    let run = run_fixture_scenario("acquire_position_behind_on_same_road.xosc", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_pose_at(&run, "Car", 7.0, 10.492948, 4.42186, 2.593647);
    assert_esmini_pose_at(&run, "Car", 8.0, 3.769623, 11.6551, 2.045702);
    assert_esmini_pose_at(&run, "Other", 8.0, 0.0, -1.75, 0.0);
}

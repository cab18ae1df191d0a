//! Routes on hand-written networks, checked against lengths computed by hand.

use crate::common;

use opendrive::{ContactPoint, RoadNetwork};
use routing::{Error, NextRoad, Route, Strategy, Waypoint};

fn idx(net: &RoadNetwork, id: &str) -> usize {
    net.road_index(id).unwrap_or(usize::MAX)
}
fn wp(net: &RoadNetwork, road: &str, lane: i32, s: f64) -> Waypoint {
    Waypoint { road: idx(net, road), lane, s, along_s: None }
}
fn roads(net: &RoadNetwork, r: &Route) -> Vec<String> {
    r.legs().iter().map(|l| format!("{}:{}", net.roads[l.road].id, l.lane)).collect()
}
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn straight_through_the_t_junction() {
    let net = common::t_junction();
    let r = Route::plan(&net, &[wp(&net, "1", -1, 50.0), wp(&net, "2", -1, 30.0)], &[], false).unwrap();
    assert_eq!(roads(&net, &r), ["1:-1", "10:-1", "2:-1"]);
    assert!(close(r.length(), 50.0 + 20.0 + 30.0), "{}", r.length());
    assert_eq!(r.next_road_after(idx(&net, "1"), true), Some(NextRoad { road: idx(&net, "10"), lane: -1, contact: ContactPoint::Start }));
    assert_eq!(r.next_road_after(idx(&net, "10"), true), Some(NextRoad { road: idx(&net, "2"), lane: -1, contact: ContactPoint::Start }));
    assert_eq!(r.next_road_after(idx(&net, "2"), true), None);
    assert_eq!(r.next_road_after(idx(&net, "1"), false), None);
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
}

#[test]
fn right_turn_needs_a_lane_change_to_the_turning_lane() {
    let net = common::t_junction();
    // Only lane -2 of road 1 connects to the right turn (road 12) into road 3 southbound (lane 1).
    let r = Route::plan(&net, &[wp(&net, "1", -1, 50.0), wp(&net, "3", 1, 40.0)], &[], false).unwrap();
    assert_eq!(roads(&net, &r), ["1:-2", "12:-1", "3:1"]);
    assert_eq!(r.legs()[0].lane_change_from, Some(-1));
    // 50 m to the junction, 15 m turn, then from s = 100 down to s = 40 against s.
    assert!(close(r.length(), 50.0 + 15.0 + 60.0));
    let last = r.legs()[2];
    assert!(!last.along_s && close(last.s_start, 100.0) && close(last.s_end, 40.0));
    assert_eq!(r.next_road_after(idx(&net, "12"), true), Some(NextRoad { road: idx(&net, "3"), lane: 1, contact: ContactPoint::End }));
}

#[test]
fn left_turn_from_the_minor_road_and_route_coordinates() {
    let net = common::t_junction();
    let r = Route::plan(&net, &[wp(&net, "3", -1, 10.0), wp(&net, "1", 1, 20.0)], &[Strategy::Shortest, Strategy::Shortest], false).unwrap();
    assert_eq!(roads(&net, &r), ["3:-1", "14:-1", "1:1"]);
    assert!(close(r.length(), 90.0 + 25.0 + 80.0));
    // route s 100 = 90 m on road 3 + 10 m into the turn
    let p = r.locate(100.0).unwrap();
    assert_eq!((net.roads[p.road].id.as_str(), p.lane), ("14", -1));
    assert!(close(p.s, 10.0) && p.along_s);
    // route s 135 = 20 m into road 1 westbound: s = 80
    let p = r.locate(135.0).unwrap();
    assert!(net.roads[p.road].id == "1" && close(p.s, 80.0) && !p.along_s);
    assert!(close(r.route_s_of(idx(&net, "1"), 80.0, None).unwrap(), 135.0));
    assert!(close(r.route_s_of(idx(&net, "3"), 55.0, None).unwrap(), 45.0));
    assert_eq!(r.route_s_of(idx(&net, "2"), 5.0, None), None);
    assert_eq!(r.waypoint_route_s(1), Some(r.length()));
    assert!(close(r.next_road_after_s(5.0).map(|n| n.road).unwrap_or(99) as f64, idx(&net, "14") as f64));
}

#[test]
fn westbound_main_road_turns_left_into_the_minor_road() {
    let net = common::t_junction();
    let r = Route::plan(&net, &[wp(&net, "2", 1, 70.0), wp(&net, "3", 1, 90.0)], &[], false).unwrap();
    assert_eq!(roads(&net, &r), ["2:1", "15:-1", "3:1"]);
    assert!(close(r.length(), 70.0 + 25.0 + 10.0));
}

#[test]
fn no_u_turns_means_no_route_back() {
    let net = common::t_junction();
    let e = Route::plan(&net, &[wp(&net, "1", -1, 50.0), wp(&net, "1", -1, 10.0)], &[], false).unwrap_err();
    assert!(matches!(e, Error::NoPath { from: 0, to: 1, .. }), "{e:?}");
}

#[test]
fn same_lane_ahead_is_a_single_leg() {
    let net = common::t_junction();
    let r = Route::plan(&net, &[wp(&net, "1", -1, 10.0), wp(&net, "1", -1, 60.0)], &[], false).unwrap();
    assert_eq!(r.legs().len(), 1);
    assert!(close(r.length(), 50.0));
}

#[test]
fn bad_waypoints_are_errors() {
    let net = common::t_junction();
    assert!(matches!(Route::plan(&net, &[wp(&net, "1", -1, 10.0)], &[], false), Err(Error::TooFewWaypoints { found: 1 })));
    let e = Route::plan(&net, &[wp(&net, "1", -3, 10.0), wp(&net, "2", -1, 10.0)], &[], false).unwrap_err();
    assert!(matches!(e, Error::BadWaypoint { index: 0, .. }));
    let bad_road = Waypoint { road: 999, lane: -1, s: 0.0, along_s: None };
    assert!(matches!(Route::plan(&net, &[wp(&net, "1", -1, 10.0), bad_road], &[], false), Err(Error::BadWaypoint { index: 1, .. })));
    let nan = Waypoint { s: f64::NAN, ..wp(&net, "1", -1, 0.0) };
    assert!(matches!(Route::plan(&net, &[nan, wp(&net, "2", -1, 10.0)], &[], false), Err(Error::BadWaypoint { index: 0, .. })));
}

#[test]
fn strategies_choose_between_the_two_ways() {
    let net = common::two_ways();
    let from = wp(&net, "A", -1, 0.0);
    let to = wp(&net, "F", -1, 50.0);
    let plan = |s: Strategy| Route::plan(&net, &[from, to], &[Strategy::Shortest, s], false).unwrap();
    // shortest: 100 + 10 + 50 + 10 + 50 = 220 through two junctions
    let short = plan(Strategy::Shortest);
    assert_eq!(roads(&net, &short), ["A:-1", "c1:-1", "B:-1", "c3:-1", "F:-1"]);
    assert!(close(short.length(), 220.0));
    // fewest junctions: via D, 100 + 10 + 500 + 50 = 660
    let few = plan(Strategy::LeastIntersections);
    assert_eq!(roads(&net, &few), ["A:-1", "c2:-1", "D:-1", "F:-1"]);
    assert!(close(few.length(), 660.0));
    // fastest: via B takes (10 + 50 + 10) / 5 = 14 s after A; via D 10/13.9 + 500/100 ≈ 5.7 s
    let fast = plan(Strategy::Fastest);
    assert_eq!(roads(&net, &fast), ["A:-1", "c2:-1", "D:-1", "F:-1"]);
    // random is planned as shortest and says so
    let rnd = plan(Strategy::Random);
    assert_eq!(rnd.legs(), short.legs());
    assert!(rnd.random_as_shortest && !short.random_as_shortest);
    assert_eq!(short.next_road_after(idx(&net, "A"), true).map(|n| n.road), Some(idx(&net, "c1")));
    assert_eq!(few.next_road_after(idx(&net, "A"), true).map(|n| n.road), Some(idx(&net, "c2")));
}

#[test]
fn intermediate_waypoints_force_the_way() {
    let net = common::two_ways();
    let r = Route::plan(&net, &[wp(&net, "A", -1, 0.0), wp(&net, "D", -1, 100.0), wp(&net, "F", -1, 50.0)], &[], false).unwrap();
    assert_eq!(roads(&net, &r), ["A:-1", "c2:-1", "D:-1", "D:-1", "F:-1"]);
    assert!(close(r.length(), 660.0));
    assert_eq!(r.waypoint_route_s(1), Some(210.0));
    assert_eq!(r.waypoint_route_s(2), Some(660.0));
}

#[test]
fn closed_route_returns_to_the_first_waypoint_and_wraps() {
    let net = common::ring();
    let r = Route::plan(&net, &[wp(&net, "R1", -1, 10.0), wp(&net, "R2", -1, 10.0)], &[], true).unwrap();
    assert!(r.is_closed());
    assert!(close(r.length(), 150.0), "{}", r.length());
    let p = r.locate(160.0).unwrap();
    assert!(net.roads[p.road].id == "R1" && close(p.s, 20.0));
    assert_eq!(r.next_road_after(idx(&net, "R2"), true).map(|n| n.road), Some(idx(&net, "R1")));
    // an open route that goes behind its start needs a lap
    let lap = Route::plan(&net, &[wp(&net, "R1", -1, 50.0), wp(&net, "R1", -1, 40.0)], &[], false).unwrap();
    assert!(close(lap.length(), 140.0));
}

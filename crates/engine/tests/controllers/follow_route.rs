//! esmini's FollowRoute controller on two straight roads in a row (fixtures `two_roads.xodr`:
//! road 1, 100 m, then road 2, 200 m, along +x; lanes −1 and −2 each 3.5 m wide, centres at
//! y = −1.75 and −5.25). Ego starts on road 1, lane −1, s = 10 at 20 m/s with the controller
//! (laneChangeTime 3 s, minDistForCollision 10 m, testMode) and gets a route to road 2,
//! lane −2, s = 50. Expected values: esmini 3.6.0 runs of the same fixture files, made for
//! these tests (`esmini_run_one.py … --max_time 12`), as noted at each number.

use crate::common::*;
use engine::Run;

fn run_fixture(name: &str) -> Run {
    run_fixture_on(name, "two_roads.xodr", 12.0)
}

#[test]
fn the_route_lane_is_taken_by_a_sinusoidal_change_and_test_mode_stops_after_the_target() {
    let run = run_fixture("follow_route_lane_change.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // The path leaves road 1 on lane −2, and the waypoint there is where Ego is (within
    // 25 m): the change starts at once and lasts 3 s. esmini: y −3.463351 at 1.5 s, lane −2's
    // centre from 3.5 s on, x 79.873861 at 3.5 s (the change costs 0.126139 m of progress).
    let e = at(&run, "Ego", 1.5);
    assert!(close(e.x, 39.939033, 1e-5) && close(e.y, -3.463351, 1e-5), "{e:?}");
    let e = at(&run, "Ego", 3.5);
    assert!(close(e.x, 79.873861, 1e-5) && close(e.y, -5.25, 1e-9), "{e:?}");
    // Passing road 2, s = 50 (x = 150) at 7.01 s ends the last waypoint; the next step
    // deactivates the controller and test mode stops Ego where the default controller moved
    // it. esmini: 20 m/s at 7.01 s, 0 from 7.02 s at x = 150.273861.
    assert!(close(at(&run, "Ego", 7.01).speed, 20.0, 1e-12));
    let e = at(&run, "Ego", 7.02);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.273861, 1e-5), "{e:?}");
    assert!(close(at(&run, "Ego", 11.0).x, 150.273861, 1e-5));
}

#[test]
fn a_vehicle_within_min_dist_for_collision_in_a_lane_between_holds_the_change_back() {
    // Blocker starts beside Ego on lane −2 at 20 m/s and slows to 10 m/s at 1 s. Ego keeps
    // missing its waypoint (planned again each step) until Blocker is 10 m away (straight-line
    // distance, 3.5 m of it sideways): esmini starts the change in the step to 1.95 s
    // (x 49.0, Blocker 39.6: 10.03 m), so y first leaves lane −1's centre at 1.96 s.
    let run = run_fixture("follow_route_blocked.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    let e = at(&run, "Ego", 1.95);
    assert!(close(e.x, 49.0, 1e-9) && close(e.y, -1.75, 1e-12), "{e:?}");
    // esmini: y −1.750096 at 1.96 s, −2.705517 at 3.0 s (x 69.972440).
    assert!(close(at(&run, "Ego", 1.96).y, -1.750096, 1e-6));
    let e = at(&run, "Ego", 3.0);
    assert!(close(e.x, 69.972440, 1e-5) && close(e.y, -2.705517, 1e-5), "{e:?}");
    // The change ends on lane −2 and test mode stops Ego past road 2, s = 50: esmini has it
    // at x = 150.273861 with speed 0 at 10 s.
    let e = at(&run, "Ego", 10.0);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.273861, 1e-5) && close(e.y, -5.25, 1e-9), "{e:?}");
}

#[test]
fn at_a_junction_the_default_controller_takes_the_connecting_road_of_the_planned_path() {
    // fixtures `fork.xodr`: road 1 (100 m along +x) ends in a junction whose first connection
    // goes straight on (road 10, to road 2) and whose second turns left (road 11, a 90° arc of
    // radius 20 m, to road 3 heading +y from (120, 20)). Without a route esmini goes straight;
    // the route to road 3 makes the path run through road 11, and passing the waypoint on
    // road 1 narrows the default controller's route to it. Ego drives at 10 m/s from s = 10.
    let run = run_fixture_on("follow_route_fork.xosc", "fork.xodr", 20.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini: on the arc (lane −1's centre has radius 21.75 m) at 11 s.
    let e = at(&run, "Ego", 11.0);
    assert!(close(e.x, 117.303578, 1e-5) && close(e.y, 6.822417, 1e-5), "{e:?}");
    // esmini: past road 3, s = 50 at 17.42 s (y 70.040395), stopped from 17.43 s at y 70.140395.
    assert!(close(at(&run, "Ego", 17.42).speed, 10.0, 1e-12));
    let e = at(&run, "Ego", 17.43);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 121.75, 1e-9) && close(e.y, 70.140395, 1e-5), "{e:?}");
}

#[test]
fn an_acquire_position_route_is_followed_like_an_assigned_one() {
    // The same drive with AcquirePositionAction (road 2, lane −2, s = 50) instead of the
    // route: esmini makes a route (Ego's position, the target) and gives the same trace as
    // follow_route_lane_change: y −3.463351 at 1.5 s, stopped at x 150.273861 from 7.02 s.
    let run = run_fixture("follow_route_acquire.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    let e = at(&run, "Ego", 1.5);
    assert!(close(e.x, 39.939033, 1e-5) && close(e.y, -3.463351, 1e-5), "{e:?}");
    let e = at(&run, "Ego", 7.02);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.273861, 1e-5) && close(e.y, -5.25, 1e-9), "{e:?}");
}

#[test]
fn test_mode_stops_for_good_when_the_init_speed_step_has_a_time_span() {
    // follow_route_lane_change with the Init SpeedAction a step "over 1 s": esmini reads a
    // step's span as 0 (ScenarioReader::ParseTransitionDynamics), so the action has ended at
    // time 0 and nothing speeds Ego up again after test mode stops it. esmini: the same trace
    // as follow_route_lane_change, 0 m/s at x 150.273861 from 7.02 s to the end.
    let run = run_fixture("follow_route_step_speed.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert!(close(at(&run, "Ego", 7.01).speed, 20.0, 1e-12));
    for t in [7.02, 9.0, 11.0] {
        let e = at(&run, "Ego", t);
        assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.273861, 1e-5), "{t}: {e:?}");
    }
}

#[test]
fn a_speed_action_started_during_the_route_lane_change_ends_at_once() {
    // follow_route_lane_change with a SpeedAction (linear over 4 s to 28 m/s) at t > 1, while
    // the 3 s lane change runs: esmini's controller is in override mode during its change, so
    // LongSpeedAction::Start ends the action at once (esmini's log: FasterAction start and
    // end at 1.01 s) and Ego keeps 20 m/s: the same trace as without it (x 39.939033 at
    // 1.5 s, 109.873861 at 5 s, stopped at 150.273861 from 7.02 s).
    let run = run_fixture("follow_route_speed_during_change.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    let e = at(&run, "Ego", 1.5);
    assert!(close(e.speed, 20.0, 1e-12) && close(e.x, 39.939033, 1e-5) && close(e.y, -3.463351, 1e-5), "{e:?}");
    let e = at(&run, "Ego", 5.0);
    assert!(close(e.speed, 20.0, 1e-12) && close(e.x, 109.873861, 1e-5), "{e:?}");
    let e = at(&run, "Ego", 7.02);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.273861, 1e-5), "{e:?}");
}

#[test]
fn a_running_speed_action_ends_when_the_route_lane_change_starts() {
    // follow_route_blocked with a SpeedAction for Ego (linear over 4 s to 28 m/s) from 1.51 s:
    // it speeds Ego up until the controller starts its lane change, then esmini's
    // LongSpeedAction::Step ends it (esmini's log: LaneChange start and FasterAction end at
    // 1.93 s) and Ego keeps 20.84 m/s. esmini: x 48.7806 at 1.93 s, 71.051665 (y −2.738346)
    // at 3 s, 112.63836 at 5 s; test mode stops Ego at x 150.35876.
    let run = run_fixture("follow_route_speed_ends_at_change.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    let e = at(&run, "Ego", 1.93);
    assert!(close(e.speed, 20.84, 1e-9) && close(e.x, 48.7806, 1e-6) && close(e.y, -1.75, 1e-12), "{e:?}");
    let e = at(&run, "Ego", 3.0);
    assert!(close(e.speed, 20.84, 1e-9) && close(e.x, 71.051665, 1e-5) && close(e.y, -2.738346, 1e-5), "{e:?}");
    assert!(close(at(&run, "Ego", 5.0).x, 112.63836, 1e-5));
    let e = at(&run, "Ego", 10.0);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.35876, 1e-5), "{e:?}");
}

#[test]
fn a_waypoint_given_in_the_world_is_followed_as_a_lane_position() {
    // follow_route_world_waypoint.xosc: the last waypoint is a WorldPosition at road 2, lane −2,
    // s = 50. esmini 3.6.0 runs it exactly as follow_route_lane_change.xosc: the change to lane
    // −2 at once (y −3.463351 at 1.5 s), then test mode stops Ego past the waypoint (speed 0
    // from 7.02 s at x = 150.273861).
    let run = run_fixture("follow_route_world_waypoint.xosc");
    let e = at(&run, "Ego", 1.5);
    assert!(close(e.x, 39.939033, 1e-5) && close(e.y, -3.463351, 1e-5), "{e:?}");
    assert!(close(at(&run, "Ego", 7.01).speed, 20.0, 1e-12));
    let e = at(&run, "Ego", 7.02);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.273861, 1e-5) && close(e.y, -5.25, 1e-9), "{e:?}");
}

#[test]
fn a_route_it_cannot_plan_stops_a_test_mode_entity_in_frame_0() {
    // follow_route_same_lane_target: Ego (20 m/s, road 1, lane −1, s = 10) gets in the Init a
    // route whose waypoints are on its own road and lane, then the controller. esmini steps
    // every active controller in frame 0 (ScenarioEngine::step, dt 0): ControllerFollowRoute
    // finds no path (LaneIndependentRouter::CalculatePath: start and target on the same road
    // and lane), deactivates, and test mode sets speed 0 there. So Ego never moves, and
    // Watcher's "Ego slower than 1 m/s" teleport (road 2, s = 100) fires in the first
    // storyboard evaluation after frame 0. esmini: Ego at x = 10 with speed 0 from 0 s on;
    // Watcher at x = 200 at 0.01 s, 200.1 at 0.02 s.
    let run = run_fixture("follow_route_same_lane_target.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    for t in [0.0, 0.01, 2.0] {
        let e = at(&run, "Ego", t);
        assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 10.0, 1e-12), "{t}: {e:?}");
    }
    assert!(close(at(&run, "Watcher", 0.01).x, 200.0, 1e-9));
    assert!(close(at(&run, "Watcher", 0.02).x, 200.1, 1e-9));
}

#[test]
fn a_scenario_waypoint_followed_by_one_on_its_road_is_dropped() {
    // Waypoints road 1 s = 20, road 1 s = 60, road 2 s = 50 (lane −1 each): esmini's
    // Route::AddWaypoint drops the waypoint at s = 60 from the scenario waypoints when the
    // next is added ("Removing previous waypoint for same road 1"), so the controller plans
    // from road 1 straight to road 2 (a path to s = 60 on Ego's own lane would not exist and
    // would deactivate it at once). esmini: 20 m/s at 7.0 s (x 150), stopped from 7.01 s at
    // x 150.2.
    let run = run_fixture("follow_route_dropped_waypoint.xosc");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    let e = at(&run, "Ego", 1.0);
    assert!(close(e.speed, 20.0, 1e-12) && close(e.x, 30.0, 1e-9), "{e:?}");
    assert!(close(at(&run, "Ego", 7.0).speed, 20.0, 1e-12));
    let e = at(&run, "Ego", 7.01);
    assert!(close(e.speed, 0.0, 1e-12) && close(e.x, 150.2, 1e-9), "{e:?}");
}

#[test]
fn a_lane_change_into_the_other_direction_misses_the_waypoint_and_no_path_is_found() {
    // Ego follows its route along road 1, lane −1 (to road 2, lane −1, s = 150) at 20 m/s; at
    // 1 s a step LaneChangeAction puts it on lane 1, still facing +s. esmini's
    // GetWaypointStatus takes "past the waypoint" in the lane's driving direction (lane 1
    // drives against s): the waypoint is missed, the path from lane 1 finds no lane to road 2's
    // lane −1 ("Path not found, deactivating controller") and test mode stops Ego. esmini:
    // 20 m/s at x 30 at 1.0 s, stopped from 1.01 s at x 30.2 on lane 1 (y 1.75).
    let run = run_fixture("follow_route_against_lane.xosc");
    for (t, x, y, v) in [(1.0, 30.0, -1.75, 20.0), (1.01, 30.2, 1.75, 0.0), (11.0, 30.2, 1.75, 0.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.speed, v, 1e-12) && close(e.x, x, 1e-9) && close(e.y, y, 1e-9), "{t}: {e:?}");
    }
}

#[test]
fn a_direct_junction_leads_the_path_search_to_its_linked_road() {
    // follow_route_direct_junction.xosc (`direct_junction_two_roads.xodr`: road 1 joins road 2
    // through a direct junction): the path to road 2, lane −2 goes through the junction's
    // linkedRoad, so the controller stays on (a path not found would switch it off and test
    // mode would stop Ego) and changes to lane −2 at once. (time, x, y) from esmini 3.6.0.
    let run = run_fixture_on("follow_route_direct_junction.xosc", "direct_junction_two_roads.xodr", 15.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    for (t, x, y) in
        [(1.0, 19.953675, -2.593453), (2.0, 29.799172, -4.343069), (3.0, 39.746512, -5.249616), (10.0, 109.746511, -5.25), (15.0, 159.746511, -5.25)]
    {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, 10.0, 1e-9), "at {t} s: {e:?}, esmini ({x}, {y})");
    }
}

/// A waypoint's routeStrategy "random" is read as shortest (ScenarioReader: only fastest and
/// leastIntersections are read), so FollowRoute's LaneIndependentRouter weighs the way by
/// length. Fixture `follow_route_random_strategy.xosc` on the left-hand T: the car stays in
/// lane -2, which leads to the target lane through the junction (esmini 3.6.0: never leaves
/// it before the junction); weighing the random leg 0 tied the way through lane -1.
#[test]
fn a_random_route_strategy_is_planned_as_the_shortest() {
    const FIXTURE: &str = "follow_route_random_strategy.xosc";
    let run = crate::common::oracle::run_fixture_scenario(FIXTURE, 20.0);
    for t in [0.5, 1.0, 2.0, 3.0] {
        let s = at(&run, "Car0", t);
        assert!(s.road.is_some_and(|r| r.lane_id == -2) && close(s.y, -5.25, 1e-9), "t {t}: {s:?}");
    }
    crate::common::oracle::assert_matches_esmini(FIXTURE, &run, 1e-3);
}

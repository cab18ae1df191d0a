//! OffroadFollower, esmini's ControllerOffroadFollower: the entity steers at the entity it
//! follows (angle to its reference point, ±1) with throttle 0.5·(distance − targetDistance) −
//! 0.5·(speed difference) on esmini's analog vehicle model, top speed 1.2 × the road's speed
//! limit. Fixture `offroad_follower.xosc` (straight road): Lead at 12 m/s changes to lane 1 at
//! t > 3; Follower starts 40 m behind in lane -2 at 5 m/s and follows it at 12 m. Expected
//! values: esmini 3.6.0 on the same fixture (osc2cr drove the follower along its lane before).
//! `offroad_follower_lateral_only.xosc`: the same, activated on the lateral domain only.
//! `straight_south.xodr`: `straight.xodr` heading south (hdg 4.7123889804).

use crate::common::*;

/// esmini 3.6.0's follower in `offroad_follower.xosc`: (t, x, y, speed).
const FOLLOWER: [(f64, f64, f64, f64); 4] =
    [(1.0, 27.519, -4.977, 10.0), (4.0, 80.018, -2.238, 25.0), (6.0, 119.463, 0.442, 13.23), (12.0, 191.909, 1.753, 12.0)];

fn assert_follower(run: &engine::Run) {
    for (t, x, y, v) in FOLLOWER {
        let e = at(run, "Follower", t);
        assert!(close(e.x, x, 2e-3) && close(e.y, y, 2e-3) && close(e.speed, v, 6e-3), "t {t}: {e:?}");
    }
}

#[test]
fn an_offroad_follower_drives_after_its_lead() {
    let run = run_fixture("offroad_follower.xosc", "straight.xodr");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_follower(&run);
}

#[test]
fn a_trajectory_waits_while_an_offroad_follower_holds_the_lateral_domain() {
    // offroad_follower_trajectory.xosc: a FollowTrajectoryAction swerving away at t > 1 s.
    // esmini's FollowTrajectoryAction::Start and ::Step return at once under a controller in
    // override mode on the lateral domain: its run is offroad_follower.xosc's to the last digit,
    // and the action runs on until the end (osc2cr drove the trajectory: 104 m away).
    let run = run_fixture("offroad_follower_trajectory.xosc", "straight.xodr");
    assert_follower(&run);
    let traj = |transition: &str| run.trace.events.iter().any(|ev| ev.element.ends_with("Traj") && ev.transition == transition);
    assert!(traj("start") && !traj("end"), "the trajectory starts and never ends by itself: {:?}", run.trace.events);
}

#[test]
fn a_lead_right_behind_turns_the_follower_left_and_frame_0_caps_its_speed() {
    // offroad_follower_behind.xosc: the lead 30 m behind in the same lane, the follower at
    // 45 m/s where its top speed is 40 m/s. esmini 3.6.0: 40 m/s already at 0 s (its controller
    // steps in frame 0 too), then a left turn (+π: GetAngleDifference) to go back.
    let run = run_fixture("offroad_follower_behind.xosc", "straight.xodr");
    for (t, x, y, v) in
        [(0.0, 80.0, -1.75, 40.0), (0.01, 80.3992, -1.749744, 39.92), (1.0, 106.793604, 5.329344, 20.0), (6.0, 109.384025, -4.070577, 13.494833)]
    {
        let e = at(&run, "Follower", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, v, 1e-4), "t {t}: {e:?}");
    }
}

#[test]
fn a_lead_right_behind_on_a_road_heading_south_turns_the_follower_left_too() {
    // offroad_follower_behind_south.xosc: the same on a road heading 4.7123889804 rad, where the
    // lead lies 4.6e-10 m west of the follower. esmini reports the follower's heading as
    // 3π/2 + 1e-6 (R0R12EulerAngles' gimbal-lock guard), which puts the lead at π − 1e-6: a
    // left turn, the east run turned by −π/2 (osc2cr turned right: 109 m away).
    let run = run_fixture("offroad_follower_behind_south.xosc", "straight_south.xodr");
    for (t, x, y, v) in [(0.01, -1.749743, -80.3992, 39.92), (1.0, 5.329371, -106.793597, 20.0), (6.0, -4.070577, -109.384024, 13.494833)] {
        let e = at(&run, "Follower", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, v, 1e-4), "t {t}: {e:?}");
    }
}

#[test]
fn an_offroad_follower_active_laterally_only_measures_after_the_default_controller_moved_it() {
    // offroad_follower_lateral_only.xosc: offroad_follower.xosc with the controller activated on
    // the lateral domain only. esmini's default controller moves the follower along its lane
    // first (ScenarioEngine::defaultController: the longitudinal domain is not overridden), so
    // the controller measures the distance to the lead from a point one step ahead; its vehicle
    // model then drives on from its own pose. Values: esmini 3.6.0 on the fixture (0.13–0.23 m
    // away from t = 5 s when the default controller is kept off).
    let run = run_fixture("offroad_follower_lateral_only.xosc", "straight.xodr");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    for (t, x, y, v) in [
        (1.0, 27.518695, -4.976945, 10.0),
        (5.0, 103.339109, -1.121961, 19.71956),
        (6.0, 119.231585, 0.441235, 13.285308),
        (8.0, 143.77127, 1.971088, 12.032209),
        (12.0, 191.789134, 1.753248, 12.00006),
    ] {
        let e = at(&run, "Follower", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, v, 1e-4), "t {t}: {e:?}");
    }
}

#[test]
fn controllers_step_in_the_order_esmini_made_them() {
    // offroad_follower_controller_order.xosc (straight road): LeadA has an ACC in override mode
    // as its ObjectController (it moves in its own Step) and FollowerA, declared after it,
    // follows it; LeadB gets the same ACC from an AssignControllerAction in the Init, so esmini
    // made that controller after FollowerB's ObjectController (ScenarioEngine::step walks
    // ScenarioReader::controller_ in that order): FollowerA steers at LeadA's new position,
    // FollowerB at LeadB's old one. Expected values: esmini 3.6.0 on the same fixture (osc2cr
    // stepped every follower before every ACC: FollowerA was off, FollowerB right).
    let run = run_fixture("offroad_follower_controller_order.xosc", "straight.xodr");
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    for (name, t, x, y, v) in [
        ("FollowerA", 5.0, 121.4170, -1.5993, 18.2489),
        ("FollowerB", 5.0, 521.2848, -1.5996, 18.1825),
        ("FollowerA", 8.0, 168.1423, -1.7603, 15.0138),
        ("FollowerB", 8.0, 567.9921, -1.7601, 15.0141),
    ] {
        let e = at(&run, name, t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, v, 1e-3), "{name} at {t}: {e:?}");
    }
}

#[test]
fn a_teleport_is_ignored_under_an_offroad_follower() {
    // offroad_follower_teleport.xosc: offroad_follower.xosc with a TeleportAction of the
    // follower 500 m along at t > 2. ControllerOffroadFollower keeps the Controller base's
    // override mode, so TeleportAction::Start does nothing (IsControllerModeOnAnyOfDomains).
    // Expected values: esmini 3.6.0 (osc2cr jumped the follower to s 500).
    let run = run_fixture("offroad_follower_teleport.xosc", "straight.xodr");
    for (t, x, y, v) in [(2.02, 40.3141, -4.0857, 15.1), (5.0, 103.4727, -1.1261, 19.8867)] {
        let e = at(&run, "Follower", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, v, 1e-3), "t {t}: {e:?}");
    }
}

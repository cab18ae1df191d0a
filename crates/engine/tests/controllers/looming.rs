//! esmini's LoomingController on a straight road (fixture `looming_straight.xosc`): Ego, set
//! speed 25 m/s and time gap 1 s, starts at 20 m/s behind a car 180 m ahead at 15 m/s. The
//! expected samples are esmini 3.6.0's (`--fixed_timestep 0.01`): the throttle rule
//! accelerates it to the set speed (5 m/s² at full throttle), then one m/s above it once the
//! car ahead is within 130 m (distance factor 1), and brakes as the gap closes. Its steering
//! wobbles when the car ahead comes within 80 m (the far point jumps to the lead's angle).

use crate::common::*;
use engine::{Run, Settings};

fn run_fixture() -> Run {
    run_straight_fixture("looming_straight.xosc", 20.0)
}

#[test]
fn the_speed_follows_esmini_looming_rule() {
    let r = run_fixture();
    // (time, x, speed) from esmini's trace
    let expected = [
        (0.0, 20.0, 20.0),
        (0.01, 20.2005, 20.05),
        (0.02, 20.4015, 20.1),
        (1.0, 42.4981, 24.6415),
        (5.0, 142.4250, 25.0),
        (6.0, 167.9597, 25.9751),
        (10.0, 271.9493, 25.9753),
        (12.0, 323.5627, 24.6959),
        (13.0, 347.1849, 22.6210),
        (15.0, 388.9906, 19.4071),
    ];
    for (t, x, v) in expected {
        let s = at(&r, "Ego", t);
        assert!(close(s.x, x, 2e-3) && close(s.speed, v, 2e-4), "at {t} s: {s:?}, esmini x {x} speed {v}");
    }
    assert!(close(at(&r, "Target", 15.0).x, 200.0 + 15.0 * 15.0, 1e-9));
}

#[test]
fn the_steering_wobbles_as_esmini_when_the_lead_becomes_the_far_point() {
    let r = run_fixture();
    // (time, y) from esmini's trace: the lane centre is at y = -1.75
    for (t, y) in [(9.0, -1.75), (10.0, -1.7287), (12.0, -1.7648), (13.0, -1.7425), (15.0, -1.7572)] {
        let s = at(&r, "Ego", t);
        assert!(close(s.y, y, 2e-3), "at {t} s: {s:?}, esmini y {y}");
    }
    assert!(r.warnings.is_empty(), "{:?}", r.warnings);
}

#[test]
fn a_lane_change_only_moves_the_lane_the_looming_car_is_locked_on() {
    // looming_lane_change.xosc: the controller holds the longitudinal domain (the SpeedAction at
    // 2 s changes nothing), the lane change at 1 s puts the position into lane -2 at once
    // (offset 3.5 m from its centre) and the looming steering swings the car towards it and far
    // beyond. (time, x, y, speed, lane, offset) from esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_lane_change.xosc", "straight.xodr");
    let expected = [
        (1.0, 32.498112, -1.75, 14.641514, -1, 0.0),
        (1.01, 32.644706, -1.750407, 14.659438, -2, 3.499593),
        (2.0, 46.503019, -6.02373, 14.997878, -2, -0.77373),
        (3.0, 55.341924, -18.088867, 14.999987, -2, -12.838867),
        (5.0, 76.364777, -37.97806, 14.999993, -2, -32.72806),
        (8.0, 107.12961, -7.03865, 14.999607, -2, -1.78865),
    ];
    for (t, x, y, v, lane, offset) in expected {
        let s = at(&r, "Ego", t);
        let road = s.road.expect("on the road");
        assert!(close(s.x, x, 1e-3) && close(s.y, y, 1e-3) && close(s.speed, v, 1e-4), "at {t} s: {s:?}, esmini ({x}, {y}) at {v} m/s");
        assert!(road.lane_id == lane && close(road.lane_offset, offset, 1e-3), "at {t} s: {road:?}, esmini lane {lane} offset {offset}");
    }
}

#[test]
fn assigned_during_a_lane_change_it_locks_the_lane_from_its_first_step_on() {
    // looming_assigned_during_lane_change.xosc: a lane change from lane -1 to -2 runs from 4.12 s;
    // the controller is assigned (both domains) at 5.11 s. ControllerLooming::Step sets the lane
    // lock, its Activate does not: the lane change stepped in the activation frame re-attaches
    // the position to lane -1 (where it is), the next one to the locked target lane -2, and the
    // probes follow. (time, x, y, speed, lane, offset) from esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_assigned_during_lane_change.xosc", "straight.xodr");
    let expected = [
        (5.12, 246.987974, -2.276976, 28.61, -1, -0.526976),
        (5.13, 247.27291, -2.286628, 28.51, -2, 2.963372),
        (6.0, 268.099226, -4.657794, 19.81, -2, 0.592206),
        (8.0, 293.465498, -3.922325, 10.700004, -2, 1.327675),
        (12.6, 342.651116, -5.242807, 10.699999, -2, 0.007193),
    ];
    for (t, x, y, v, lane, offset) in expected {
        let s = at(&r, "Ego", t);
        let road = s.road.expect("on the road");
        assert!(close(s.x, x, 1e-3) && close(s.y, y, 1e-3) && close(s.speed, v, 1e-4), "at {t} s: {s:?}, esmini ({x}, {y}) at {v} m/s");
        assert!(road.lane_id == lane && close(road.lane_offset, offset, 1e-3), "at {t} s: {road:?}, esmini lane {lane} offset {offset}");
    }
}

#[test]
fn a_lane_change_onto_a_border_lane_leaves_the_looming_car_in_the_driving_lane() {
    // looming_lane_change_onto_border.xosc (bay.xodr): the lane change from lane -2 towards the
    // border lane -3 puts the position, locked on its lane, in the driving lane nearest lane
    // -3's centre (-2, XYZ2TrackPos with lockOnLane_), at the lane change's point and heading,
    // from where the controller looks before it places the car: the steering swings the car
    // left, off the road. (time, x, y, speed, lane, offset) from esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_lane_change_onto_border.xosc", "bay.xodr");
    let expected = [
        (1.01, 22.644707, -5.000332, 14.659438, -2, -0.000332),
        (1.5, 29.927425, -4.742871, 14.972416, -2, 0.257129),
        (2.0, 37.20765, -3.066532, 14.997878, -2, 1.933468),
        (3.0, 47.007952, 7.509488, 14.999987, -2, 12.509488),
        (4.0, 47.379432, 22.461644, 14.998785, -2, 27.461644),
        (6.0, 26.181054, 35.219927, 14.999309, -2, 40.219927),
    ];
    for (t, x, y, v, lane, offset) in expected {
        let s = at(&r, "Ego", t);
        let road = s.road.expect("on the road");
        assert!(close(s.x, x, 1e-3) && close(s.y, y, 1e-3) && close(s.speed, v, 1e-4), "at {t} s: {s:?}, esmini ({x}, {y}) at {v} m/s");
        assert!(road.lane_id == lane && close(road.lane_offset, offset, 1e-3), "at {t} s: {road:?}, esmini lane {lane} offset {offset}");
    }
}

#[test]
fn activated_laterally_it_turns_the_car_to_the_driving_direction_and_stays_inactive() {
    // looming_lateral_activation.xosc: lane 1 drives against s; the car starts facing along s.
    // esmini 3.6.0 turns it round on activation (Controller::Activate: AlignToRoadHeading); the
    // default controller and the SpeedAction at 2 s (10 -> 30 m/s in 2 s) drive it.
    let r = crate::common::run_fixture("looming_lateral_activation.xosc", "straight.xodr");
    for (t, x, v) in [(0.0, 200.0, 10.0), (2.0, 180.0, 10.0), (3.0, 167.475, 15.0), (4.0, 149.95, 20.0), (8.0, 39.9, 30.0)] {
        let s = at(&r, "Ego", t);
        assert!(
            close(s.x, x, 1e-3) && close(s.y, 1.75, 1e-6) && close(s.h, std::f64::consts::PI, 1e-6) && close(s.speed, v, 1e-6),
            "at {t} s: {s:?}, esmini x {x} speed {v}"
        );
    }
}

fn corpus_run(name: &str) -> Option<Run> {
    let shared = std::env::var_os("OSC2CR_SHARED")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    let path = shared.join("corpus/esmini-unittest/EnvironmentSimulator/Unittest/xosc").join(name);
    let Ok((scenario, _)) = openscenario::load_scenario(&path, &Default::default()) else {
        eprintln!("corpus not found: test skipped");
        return None;
    };
    let net = scenario.road_network.logic_file.as_ref().and_then(|p| opendrive::load(p).ok()).map(|l| l.network);
    Some(engine::simulate(&scenario, net.as_ref(), &Settings::default()).expect("simulate"))
}

#[test]
fn looming_hw_follows_the_curves_as_esmini() {
    // The corpus scenario loomingHW (simple_highway: spirals and arcs): Ego's looming steering
    // takes it off the lane centre in the curves; esmini 3.6.0's positions.
    let Some(r) = corpus_run("loomingHW.xosc") else { return };
    for (t, x, y) in [(5.0, 202.7582, -4.7129), (8.94, 322.3561, 7.5134), (10.0, 354.0641, 14.3929), (14.0, 470.2843, 48.6079), (19.5, 594.5103, 86.8727)] {
        let s = at(&r, "Ego", t);
        assert!(close(s.x, x, 0.01) && close(s.y, y, 0.01), "at {t} s: {s:?}, esmini ({x}, {y})");
    }
}

#[test]
fn looming_advanced_test_goes_through_the_junction_as_esmini() {
    // loomingAdvancedTest: curves, then straight through a junction behind a car that turns
    // off (still the lead: Position::Delta finds the path to its connecting road). The car's
    // speed-up is triggered by a road-coordinate distance across roads, measured along the
    // road path (Position::Distance): at 21.09 s as in esmini, not 21.10 s as the straight
    // line gives. The run ends at the end of the road at 41.38 s.
    let Some(r) = corpus_run("loomingAdvancedTest.xosc") else { return };
    assert_eq!(event_time(&r, "Event", "start"), Some(21.09));
    for (t, x, y) in [(10.0, -257.1052, 15.0229), (20.0, -112.8317, 10.9837), (29.15, 18.7197, -1.5799), (35.0, 101.5878, -1.5010), (41.38, 190.1904, -1.5004)]
    {
        let s = at(&r, "Ego", t);
        assert!(close(s.x, x, 0.01) && close(s.y, y, 0.01), "at {t} s: {s:?}, esmini ({x}, {y})");
    }
    assert!(close(r.trace.end_time(), 41.38, 1e-9), "{}", r.trace.end_time());
}

#[test]
fn at_a_t_junction_the_probes_draw_and_the_car_takes_the_arm_esmini_attaches_it_to() {
    // looming_tee.xosc on tee_lht.xodr (the difftest generator's left-hand-traffic T): the car
    // drives up the stem (road 3) into the junction alone. Its lane-centre probes at 10 and 80 m
    // cross the junction, whose two arms turn alike: each probe takes its arm by a draw from
    // esmini's generator (Position::MoveToConnectingRoad, junction selector angle 0), so the far
    // point flips between the arms and the car wobbles before the junction. Entering it, the
    // car's world pose is attached to the later arm in the file (road 105, turning left:
    // Position::XYZ2TrackPos prefers among directly connected roads the one that bends least,
    // a later one at equal bend). (entity, time, x, y, h) from esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_tee.xosc", "tee_lht.xodr");
    let rows = [
        ("Ego", 5.0, -1.702535, -65.009038, 1.576907),
        ("Ego", 6.0, -1.831787, -50.011303, 1.571637),
        ("Ego", 8.0, -1.699638, -20.017195, 1.551424),
        ("Ego", 8.5, -3.090714, -12.726137, 1.978605),
        ("Ego", 9.0, -8.13998, -7.295732, 2.520276),
        ("Ego", 10.0, -22.246439, -2.436198, 2.934438),
        ("Ego", 12.0, -52.131593, -0.697289, 3.161905),
    ];
    crate::common::assert_esmini_poses(&r, &rows, 1e-3, 1e-4);
    let road = at(&r, "Ego", 8.5).road.expect("on a road");
    assert_eq!(road.road, 8, "the left arm, road 105 (the ninth road): {road:?}");
}

#[test]
fn past_a_dead_end_the_far_tangent_search_skips_the_lanes_last_osi_point() {
    // looming_past_road_end.xosc: the car drives past the dead end of straight.xodr (s = 1000),
    // steers round and comes back. Beyond the end esmini's position has the s of the reference
    // line's last OSI point, SMALL_NUMBER / 2 short of the end (Position::XYZ2TrackPos), so once
    // the car faces back (4.05 s) the far-tangent search does not take the lane's last OSI point
    // as ahead of it and the far point is the lane centre 80 m back. (entity, time, x, y, h)
    // from esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_past_road_end.xosc", "straight.xodr");
    let rows = [
        ("Ego", 3.0, 1004.961057, -2.199819, 6.094282),
        ("Ego", 4.5, 1011.253239, -19.888874, 4.117776),
        ("Ego", 5.0, 1005.331432, -24.341426, 3.569078),
        ("Ego", 6.0, 990.620133, -24.079161, 2.860964),
        ("Ego", 8.0, 964.706055, -9.207752, 2.624917),
        ("Ego", 10.0, 936.20899, -0.294334, 3.018246),
        ("Ego", 12.0, 906.260109, -0.837463, 3.197896),
    ];
    crate::common::assert_esmini_poses(&r, &rows, 1e-3, 1e-4);
}

#[test]
fn past_a_dead_end_along_y_the_micro_radian_of_esmini_heading_picks_the_turn() {
    // looming_dead_end_along_y.xosc on tee_lht.xodr: the car drives along road 3 (heading
    // 4.7123889804, along -y) past its dead end at s = 300. esmini's position reports a heading
    // within 1e-6 rad of 3π/2 as 3π/2 + 1e-6 (Position::EvaluateHPR, R0R12EulerAngles'
    // gimbal-lock guard); the vehicle model starts from that heading, the probes turn by it
    // and every placement passes it again, and which way the car turns once its probes,
    // stopped at the road's end, fall behind it follows from that micro-radian.
    // (entity, time, x, y, h) from esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_dead_end_along_y.xosc", "tee_lht.xodr");
    let rows = [
        ("Ego", 1.5, 0.969159, -326.149926, 4.437908),
        ("Ego", 2.0, -3.477967, -332.014564, 3.786154),
        ("Ego", 3.0, -17.311176, -330.520400, 2.453379),
        ("Ego", 4.0, -21.854779, -316.815470, 1.501625),
        ("Ego", 5.0, -17.198514, -302.656783, 1.098326),
        ("Ego", 6.0, -9.052983, -290.079947, 0.965721),
        ("Ego", 8.0, 2.081983, -262.425922, 1.347107),
    ];
    crate::common::assert_esmini_poses(&r, &rows, 1e-3, 1e-4);
}

#[test]
fn a_looming_car_drifting_off_its_connecting_road_stays_on_it() {
    // looming_beside_connecting_road.xosc on crossing.xodr: the car crosses the junction on the
    // straight connecting road 106 (right lanes only), its lane offset action drifting it a few
    // cm left of the reference line, where only the crossing connecting roads (107, 111) have
    // lanes. esmini's XYZ2TrackPos keeps a point within 2 m of the current road on it and
    // weighs roads not directly connected to it 3 m more: the car stays on road 106, lane -1,
    // its offset from that lane's centre (1.86 m at 4.1 s). (time, x, y, h, lane, offset) from
    // esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_beside_connecting_road.xosc", "crossing.xodr");
    let rows = [
        (3.9, -5.116806, -0.040916, 0.068995, -1, 1.709084),
        (4.1, -1.564568, 0.109449, 0.027177, -1, 1.859449),
        (4.5, 5.545284, -0.016417, 6.246402, -1, 1.733583),
        (5.0, 14.424417, -0.41837, 6.233994, -1, 1.33163),
        (6.0, 32.183834, -1.232425, 6.24488, -1, 0.517575),
        (6.25, 36.626128, -1.386536, 6.250495, -1, 0.363464),
    ];
    for (t, x, y, h, lane, offset) in rows {
        crate::common::assert_esmini_poses(&r, &[("Ego", t, x, y, h)], 1e-3, 1e-4);
        let road = at(&r, "Ego", t).road.expect("on the road");
        assert!(road.lane_id == lane && close(road.lane_offset, offset, 1e-3), "at {t} s: {road:?}, esmini lane {lane} offset {offset}");
    }
}

#[test]
fn over_a_ridge_the_looming_car_looks_along_osi_points_cut_at_the_slope_break() {
    // looming_over_a_ridge.xosc on hill.xodr: the car drives up the ridge (slope 0.5, then
    // −0.5 from s = 50) and past the dead end at s = 100, where its far point is the tangent
    // point of the lane's edges. esmini's lane OSI points are cut where the slope jumps
    // (OpenDrive::CheckAndAddOSIPoint with GetMaxSegmentLen: a change of slope above 0.1 is a
    // discontinuity), not one 50 m chord over the top as on a flat road; the tangent point,
    // and so the turn past the end, follows from those points. (entity, time, x, y, h) from
    // esmini 3.6.0's trace.
    let r = crate::common::run_fixture("looming_over_a_ridge.xosc", "hill.xodr");
    let rows = [
        ("Ego", 5.0, 94.991184, -1.75, 0.0),
        ("Ego", 7.0, 112.595634, -17.705746, 4.309142),
        ("Ego", 7.5, 107.218601, -22.704072, 3.59818),
        ("Ego", 8.0, 99.879142, -22.955078, 2.863094),
        ("Ego", 9.0, 86.954752, -15.464888, 2.472566),
        ("Ego", 10.0, 74.079695, -7.831436, 2.67867),
        ("Ego", 12.0, 44.704649, -2.581182, 3.062575),
    ];
    crate::common::assert_esmini_poses(&r, &rows, 1e-3, 1e-4);
}

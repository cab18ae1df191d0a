//! esmini's NaturalDriver controller on the straight fixture road (1000 m along +x; lanes -1 and
//! -2 on the right, 3.5 m wide, centres at y = -1.75 and y = -5.25), against hand computations.
//! Cars are 4.5 m long with the box centre 1.5 m ahead of the reference point, so the free space
//! between a follower and its leader is the reference-point distance minus 3.75 m + 0.75 m.
//! The driver: desired speed 20 m/s, desired distance 5 m, time headway 1.5 s, maxAcc 2 m/s²,
//! maxDec -4 m/s², lane change over 3 s, route lane -1 (unless a test says otherwise).

use crate::common::{at, car_with, close, event_time, run_on};
use engine::{Run, Settings};

const DT: f64 = 0.01;
const V0: f64 = 20.0;
const A: f64 = 2.0;
const B: f64 = 4.0;
const S0: f64 = 5.0;
const T: f64 = 1.5;
/// Follower overhang ahead of its reference point plus leader overhang behind its own.
const OVERHANG: f64 = 3.75 + 0.75;

fn natural_driver(extra: &str) -> String {
    let props: String = [
        ("desiredDistance", "5"),
        ("desiredSpeed", "20"),
        ("laneChangeDuration", "3"),
        ("lookAheadDistance", "100"),
        ("maxDec", "-4"),
        ("maxAcc", "2"),
        ("laneChangeDelay", "1"),
        ("thw", "1.5"),
        ("maxImposedBraking", "3"),
        ("politeness", "0.1"),
        ("route", "-1"),
        ("mode", "override"),
    ]
    .iter()
    .map(|(k, v)| format!(r#"<Property name="{k}" value="{v}"/>"#))
    .collect();
    format!(r#"<ObjectController><Controller name="NaturalDriver"><Properties>{props}{extra}</Properties></Controller></ObjectController>"#)
}

fn place(entity: &str, s: f64, lane: i32, speed: f64) -> String {
    format!(
        r#"<Private entityRef="{entity}"><PrivateAction><TeleportAction><Position><LanePosition roadId="1" laneId="{lane}" offset="0" s="{s}"/></Position></TeleportAction></PrivateAction><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>{}</Private>"#,
        if entity == "Ego" { r#"<PrivateAction><ActivateControllerAction longitudinal="true" lateral="false"/></PrivateAction>"# } else { "" }
    )
}

/// Ego (with the driver, `extra` properties added) and two plain cars placed by `init`.
fn scenario(extra: &str, init: &str, stop: f64) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="1" date="2024-01-01T00:00:00" description="test" author="osc2cr"/>
<CatalogLocations/>
<RoadNetwork><LogicFile filepath="straight.xodr"/></RoadNetwork>
<Entities>{}{}{}</Entities>
<Storyboard>
<Init><Actions>{init}</Actions></Init>
<StopTrigger><ConditionGroup><Condition name="end" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{stop}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>
</Storyboard>
</OpenSCENARIO>"#,
        car_with("Ego", &natural_driver(extra)),
        car_with("Target", ""),
        car_with("Blocker", "")
    )
}

fn run(text: &str, max_time: f64) -> Run {
    run_on(text, "straight.xodr", &Settings { step: DT, max_time })
}

/// Ego with the driver (lane-change gain threshold `gain`) and the two other cars placed as
/// `init` says, run until `stop`.
fn drive_with_gain(gain: f64, init: [String; 3], stop: f64) -> Run {
    let text = scenario(&format!(r#"<Property name="laneChangeAccGain" value="{gain}"/>"#), &init.concat(), stop);
    run(&text, stop)
}

/// Parked far away, out of every look-ahead.
fn parked(entity: &str) -> String {
    place(entity, 950.0, -2, 0.0)
}

#[test]
fn free_driving_approaches_the_desired_speed_as_idm_says() {
    // Alone on the road from standstill: each step v += a·(1 − (v/v0)⁴)·dt, then x += v·dt
    // (esmini's explicit Euler, the speed of the previous frame in the formula).
    let run = run(&scenario("", &format!("{}{}{}", place("Ego", 10.0, -1, 0.0), parked("Target"), parked("Blocker")), 30.0), 30.0);
    assert!(!run.warnings.iter().any(|w| w.message.contains("NaturalDriver")), "{:?}", run.warnings);
    let (mut v, mut x) = (0.0_f64, 10.0_f64);
    for k in 1..=2000 {
        v += A * (1.0 - (v / V0).powi(4)) * DT;
        x += v * DT;
        let t = k as f64 * DT;
        if k % 250 == 0 {
            let e = at(&run, "Ego", t);
            assert!(close(e.speed, v, 1e-9), "t={t}: {} vs {v}", e.speed);
            assert!(close(e.x, x, 1e-6), "t={t}: {} vs {x}", e.x);
            assert!(close(e.y, -1.75, 1e-9), "stays in its lane");
        }
    }
    // Starts at maxAcc, never exceeds the desired speed, and gets within 1 % of it by 20 s.
    assert!(close(at(&run, "Ego", DT).speed, A * DT, 1e-12));
    assert!(at(&run, "Ego", 20.0).speed > 0.99 * V0 && at(&run, "Ego", 29.0).speed <= V0);
}

#[test]
fn following_a_slower_car_settles_at_the_idm_equilibrium_gap() {
    // A lane change never pays (gain threshold 1000). Behind a car at v = 10 m/s the IDM is at
    // rest when a·(1 − (v/v0)⁴) = a·(s*/s)² with s* = s0 + v·T (no closing speed):
    // s = 20 / √(1 − 1/16) = 20.656 m of free space. The driver measures it after the leader
    // moved and before its own move (esmini steps controllers last), so the recorded gap is
    // v·dt = 0.1 m shorter.
    let run = drive_with_gain(1000.0, [place("Ego", 10.0, -1, 10.0), place("Target", 60.0, -1, 10.0), parked("Blocker")], 60.0);
    let gap = (S0 + 10.0 * T) / (1.0 - (10.0_f64 / V0).powi(4)).sqrt() - 10.0 * DT;
    let (e, g) = (at(&run, "Ego", 59.0), at(&run, "Target", 59.0));
    assert!(close(g.x - e.x - OVERHANG, gap, 0.005), "free space {} vs {gap}", g.x - e.x - OVERHANG);
    assert!(close(e.speed, 10.0, 0.01), "{}", e.speed);
    assert!(close(e.y, -1.75, 1e-9), "no lane change");
    assert!(event_time(&run, "LaneChangeAction_0", "start").is_none());
}

#[test]
fn overtakes_into_a_free_lane_at_once_and_holds_its_speed_meanwhile() {
    // At 20 m/s, 40 m behind a car at 10 m/s, the IDM brakes hard (s* = 5 + 30 + 20·10/(2·√8)
    // = 70.4 m against 35.5 m of free space); in the empty lane -2 it would not brake at all:
    // the MOBIL gain is far above 0.3, so the driver injects a lane change on the first frame.
    // It starts on the next (storyboard time 0), runs 3 s sinusoidally from y = -1.75 to -5.25
    // (param = t - 0.01 at row t: half way at row 1.51), and the speed stays 20 m/s meanwhile.
    let run = drive_with_gain(0.3, [place("Ego", 10.0, -1, 20.0), place("Target", 50.0, -1, 10.0), parked("Blocker")], 6.0);
    assert_eq!(event_time(&run, "LaneChangeAction_0", "start"), Some(0.0));
    let end = event_time(&run, "LaneChangeAction_0", "end").expect("lane change ends");
    assert!(close(end, 3.0, 1e-6), "{end}");
    let y = |t: f64| at(&run, "Ego", t).y;
    assert!(close(y(0.01), -1.75, 1e-9));
    assert!(close(y(1.51), -3.5, 1e-6), "{}", y(1.51));
    let quarter = -1.75 - 3.5 * (1.0 - (std::f64::consts::PI * 0.75 / 3.0).cos()) / 2.0;
    assert!(close(y(0.76), quarter, 1e-6), "{} vs {quarter}", y(0.76));
    assert!(close(y(3.5), -5.25, 1e-9));
    for t in [0.5, 1.5, 2.5, 3.0] {
        assert!(close(at(&run, "Ego", t).speed, 20.0, 1e-12), "t={t}");
    }
    // In the free lane it keeps its desired speed.
    assert!(close(at(&run, "Ego", 5.0).speed, V0, 1e-9));
}

#[test]
fn does_not_change_into_an_occupied_lane() {
    // Same start, but a car drives alongside in lane -2 at 20 m/s. Behind it the free space is 0,
    // so the predicted acceleration there is hopeless and no change is tried; braking at most
    // 4 m/s² the Ego falls at most 2 m behind within 1 s, still less than the 4.5 m the boxes
    // overlap, so for that second it stays in lane -1.
    let run = drive_with_gain(0.3, [place("Ego", 10.0, -1, 20.0), place("Target", 50.0, -1, 10.0), place("Blocker", 10.0, -2, 20.0)], 6.0);
    let start = event_time(&run, "LaneChangeAction_0", "start");
    assert!(start.is_none_or(|t| t > 1.0), "{start:?}");
    assert!(close(at(&run, "Ego", 1.0).y, -1.75, 1e-9));
    // It brakes at maxDec meanwhile (the IDM asks for more).
    assert!(close(at(&run, "Ego", 0.5).speed, 20.0 - B * 0.5, 1e-9), "{}", at(&run, "Ego", 0.5).speed);
}

#[test]
fn returns_to_its_route_lane_when_that_is_free_and_stays_there() {
    // Alone in lane -2 at its desired speed with route lane -1: into the route lane only the
    // braking limits count (nobody brakes on an empty road), so it changes at once although
    // nothing is gained; back in lane -1, lane -2 gains nothing (0 < 0.3) and it stays.
    let run = drive_with_gain(0.3, [place("Ego", 10.0, -2, 20.0), parked("Target"), parked("Blocker")], 10.0);
    assert_eq!(event_time(&run, "LaneChangeAction_0", "start"), Some(0.0));
    assert!(close(at(&run, "Ego", 1.51).y, -3.5, 1e-6));
    assert!(close(at(&run, "Ego", 9.9).y, -1.75, 1e-9));
    assert!(event_time(&run, "LaneChangeAction_1", "start").is_none());
}

#[test]
fn a_positive_max_dec_is_the_least_acceleration_as_in_esmini() {
    // natural_driver_positive_max_dec.xosc: alone, 5 -> 20 m/s, maxAcc 3, maxDec +2. esmini
    // 3.6.0 clips the IDM acceleration from below at maxDec: 2 m/s² between 5 s and 6 s, where
    // the IDM alone would give 3·(1 − (v/20)⁴) ≈ 0.7 m/s².
    let run = crate::common::run_fixture("natural_driver_positive_max_dec.xosc", "straight.xodr");
    for (t, x, v) in [(1.0, 26.501811, 7.963631), (3.0, 48.064605, 13.397386), (5.0, 79.170758, 17.566059), (6.0, 97.746817, 19.566059), (8.0, 137.70189, 20.0)]
    {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.speed, v, 1e-4), "t {t}: {e:?}");
    }
}

#[test]
fn in_additive_mode_the_default_controller_moves_the_car_too() {
    // natural_driver_additive_alone.xosc: alone at its desired 10 m/s, mode additive. esmini 3.6.0
    // moves it by the default controller and again by the driver: x = 20 + 20 t at 10 m/s.
    let run = crate::common::run_fixture("natural_driver_additive_alone.xosc", "straight.xodr");
    for t in [0.01, 1.0, 4.0, 8.0] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, 20.0 + 20.0 * t, 1e-6) && close(e.speed, 10.0, 1e-9), "t {t}: {e:?}");
    }
}

#[test]
fn the_lane_change_cooldown_counts_a_double_duration() {
    // Fixture natural_driver_cooldown.xosc: the overtake above at 15 m/s with a lane change of
    // 3.78 s. ControllerNaturalDriver keeps laneChangeDuration as a double: its cooldown
    // (3.78 + 1 s, less dt each step) reaches the delay only after 379 steps, so the speed is
    // held through row 3.79 and the IDM acceleration shows from row 3.80 (a float 3.78 ends
    // one step sooner). esmini 3.6.0: 15 m/s at 3.79 s, 15.013672 at 3.80 s, 15.027321 at 3.81 s.
    let run = crate::common::run_fixture("natural_driver_cooldown.xosc", "straight.xodr");
    for (t, v) in [(3.78, 15.0), (3.79, 15.0), (3.8, 15.013672), (3.81, 15.027321)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.speed, v, 1e-5), "t={t}: {e:?}");
    }
    assert!(close(at(&run, "Ego", 3.79).y, -5.25, 1e-9));
}

//! What a closed-loop step does with each kind of input, on the straight fixture road: a
//! state puts the entity there, driver input drives esmini's vehicle model, dead reckoning
//! goes on at the last state's speed, hold keeps it; wrong inputs are refused with a message
//! naming them; the storyboard's motion actions on an external entity yield as esmini's do;
//! an outside driver's controller makes its entity external from its activation on; the same
//! inputs give the same run.

use crate::common::*;
use engine::{DriverInput, External, ExternalState, Input, RunControl, ScriptedMotion, Settings, Simulation};

fn load(text: &str) -> (openscenario::Scenario, opendrive::RoadNetwork) {
    (scenario_of(text), fixture_road("straight.xodr"))
}

/// Ego at s = 50 on lane −1 at 10 m/s, Target at s = 200 on lane −1 at 5 m/s; `stories`; 10 s.
fn scenario(stories: &str) -> String {
    let init = format!("{}{}", placed("Ego", 50.0, -1, 10.0), placed("Target", 200.0, -1, 5.0));
    xosc(&init, stories, &stop_at(10.0))
}

const EGO: usize = 0;
const TARGET: usize = 1;

fn settings() -> Settings {
    Settings { step: 0.01, max_time: 10.0 }
}

/// Runs `text` with Ego external, its input each step from `input(time of the step's end)`.
fn drive(text: &str, external: &External, mut input: impl FnMut(f64, &Simulation) -> Vec<(usize, Input)>) -> engine::Run {
    let (scenario, net) = load(text);
    let mut sim = Simulation::new(&scenario, Some(&net), &settings(), &RunControl::default(), external).expect("starts");
    while !sim.is_over() {
        let inputs = input(sim.time() + 0.01, &sim);
        sim.step_with(&inputs).expect("steps");
    }
    sim.finish()
}

#[test]
fn a_state_puts_the_entity_where_it_says() {
    let run = drive(&scenario(""), &External::named(["Ego"]), |t, _| {
        let state = ExternalState { yaw_rate: Some(0.25), ..ExternalState::new(50.0 + 4.0 * t, -1.75 - 0.1 * t, 0.05, 4.0) };
        vec![(EGO, Input::State(state))]
    });
    let s = at(&run, "Ego", 2.0);
    assert!(close(s.x, 58.0, 1e-9) && close(s.y, -1.95, 1e-9) && close(s.h, 0.05, 1e-12) && s.speed == 4.0, "{s:?}");
    assert_eq!(s.yaw_rate, 0.25);
    // on the road: its lane and s follow from the pose
    let road = s.road.expect("on the road");
    assert_eq!(road.lane_id, -1);
    assert!(close(road.s, 58.0, 1e-9), "{road:?}");
    // the others go on as scripted
    assert!(close(at(&run, "Target", 2.0).x, 210.0, 1e-9));
}

#[test]
fn driver_input_drives_esminis_vehicle_model() {
    // full throttle: 20 m/s² from 10 m/s, esmini's UDP driver's limit of 30 m/s after 1 s
    let run = drive(&scenario(""), &External::named(["Ego"]), |_, _| vec![(EGO, Input::Driver(DriverInput { throttle: 1.0, brake: 0.0, steering: 0.0 }))]);
    assert!(close(at(&run, "Ego", 0.5).speed, 20.0, 1e-9), "{:?}", at(&run, "Ego", 0.5));
    assert!(close(at(&run, "Ego", 2.0).speed, 30.0, 1e-9));
    // 0.5 s at 10 + 20 t (each step moves at the new speed), then straight on in its lane
    let s = at(&run, "Ego", 0.5);
    let expected = 50.0 + (1..=50).map(|k| 0.01 * (10.0 + 0.2 * k as f64)).sum::<f64>();
    assert!(close(s.x, expected, 1e-9) && close(s.y, -1.75, 1e-12), "{s:?} vs x = {expected}");
    // braking to a stop holds the car there
    let run = drive(&scenario(""), &External::named(["Ego"]), |_, _| vec![(EGO, Input::Driver(DriverInput { throttle: 0.0, brake: 1.0, steering: 0.0 }))]);
    assert_eq!(at(&run, "Ego", 1.0).speed, 0.0);
    assert_eq!(at(&run, "Ego", 1.0).x, at(&run, "Ego", 5.0).x);
    // steering left turns it left
    let run = drive(&scenario(""), &External::named(["Ego"]), |_, _| vec![(EGO, Input::Driver(DriverInput { throttle: 0.0, brake: 0.0, steering: 0.3 }))]);
    let s = at(&run, "Ego", 1.0);
    assert!(s.y > -1.75 + 0.1 && s.h > 0.01 && s.h < 1.0, "{s:?}");
}

#[test]
fn dead_reckoning_goes_on_and_hold_stays() {
    let run = drive(&scenario(""), &External::named(["Ego"]), |t, _| {
        let input = if t < 1.0 + 1e-9 { Input::State(ExternalState::new(60.0, -1.75, 0.0, 8.0)) } else { Input::DeadReckon };
        vec![(EGO, input)]
    });
    assert!(close(at(&run, "Ego", 1.0).x, 60.0, 1e-12));
    assert!(close(at(&run, "Ego", 2.0).x, 68.0, 1e-9), "{:?}", at(&run, "Ego", 2.0));
    // backwards: esmini derives a dead-reckoned entity's speed from its displacement
    let run = drive(&scenario(""), &External::named(["Ego"]), |t, _| {
        let input = if t < 1.0 + 1e-9 { Input::State(ExternalState::new(60.0, -1.75, 0.0, -8.0)) } else { Input::DeadReckon };
        vec![(EGO, input)]
    });
    assert_eq!(at(&run, "Ego", 1.0).speed, -8.0);
    let s = at(&run, "Ego", 2.0);
    assert!(close(s.x, 52.0, 1e-9) && s.speed == 8.0, "{s:?}");
    // no state given yet: dead reckoning holds it
    let run = drive(&scenario(""), &External::named(["Ego"]), |_, _| vec![(EGO, Input::DeadReckon)]);
    let s = at(&run, "Ego", 3.0);
    assert!(close(s.x, 50.0, 1e-12) && s.speed == 0.0, "{s:?}");
    let run = drive(&scenario(""), &External::named(["Ego"]), |_, _| vec![(EGO, Input::Hold)]);
    // where Init put it, standing
    let s = at(&run, "Ego", 3.0);
    assert!(close(s.x, 50.0, 1e-12) && s.speed == 0.0, "{s:?}");
}

#[test]
fn wrong_inputs_are_refused_by_name_and_the_step_is_not_run() {
    let (scenario, net) = load(&scenario(""));
    assert!(
        matches!(Simulation::new(&scenario, Some(&net), &settings(), &RunControl::default(), &External::named(["Nobody"])), Err(engine::Error::Input(m)) if m.contains("no entity named `Nobody`") && m.contains("Ego, Target"))
    );
    let mut sim = Simulation::new(&scenario, Some(&net), &settings(), &RunControl::default(), &External::named(["Ego"])).expect("starts");
    let message = |r: Result<bool, engine::Error>| match r {
        Err(engine::Error::Input(m)) => m,
        other => panic!("expected an input error, got {other:?}"),
    };
    assert!(message(sim.step_with(&[])).contains("no input for `Ego`"));
    assert!(message(sim.step_with(&[(TARGET, Input::Hold)])).contains("`Target` is not driven from outside (Ego is)"));
    assert!(message(sim.step_with(&[(EGO, Input::State(ExternalState::new(f64::NAN, 0.0, 0.0, 0.0)))])).contains("input for `Ego`: x is NaN"));
    assert!(message(sim.step_with(&[(EGO, Input::Hold), (EGO, Input::Hold)])).contains("two inputs for `Ego`"));
    assert!(message(sim.step_with(&[(7, Input::Hold)])).contains("no entity with index 7"));
    // nothing ran
    assert_eq!(sim.time(), 0.0);
    assert!(sim.step_with(&[(EGO, Input::Hold)]).expect("a right input steps"));
    assert!(close(sim.time(), 0.01, 1e-12));
}

/// A story for Ego: at 1 s a speed change to 20 m/s over 2 s and a lane change to lane −2 over 2 s.
fn ego_story() -> String {
    story("Ego", &ego_events())
}

/// The events of `ego_story`.
fn ego_events() -> String {
    let speed = event("Faster", "parallel", &speed_action("linear", "time", 2.0, 20.0), &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)));
    let lane = event(
        "Over",
        "parallel",
        r#"<PrivateAction><LateralAction><LaneChangeAction><LaneChangeActionDynamics dynamicsShape="sinusoidal" value="2" dynamicsDimension="time"/><LaneChangeTarget><AbsoluteTargetLane value="-2"/></LaneChangeTarget></LaneChangeAction></LateralAction></PrivateAction>"#,
        &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)),
    );
    format!("{speed}{lane}")
}

#[test]
fn the_storyboards_motion_actions_yield_to_the_outside_as_esminis_do() {
    let hold = |_: f64, _: &Simulation| vec![(EGO, Input::Hold)];
    let run = drive(&scenario(&ego_story()), &External::named(["Ego"]), hold);
    // the speed change ends at once, the lane change runs on without end; neither moves Ego
    assert_eq!(event_time(&run, "FasterAction", "end"), Some(1.0));
    assert_eq!(event_time(&run, "OverAction", "end"), None);
    assert!(close(at(&run, "Ego", 5.0).x, 50.0, 1e-12) && close(at(&run, "Ego", 5.0).y, -1.75, 1e-12));
    for element in ["SpeedAction", "LaneChangeAction"] {
        assert!(
            run.warnings.iter().any(|w| w.message.starts_with(&format!("{element} on `Ego`: the entity is driven from outside"))),
            "{element}: {:?}",
            run.warnings
        );
    }
    // replaced instead: the actions run their course from where the outside put the entity
    // each step (here: standing at s = 50), the outside's state is what everyone sees. Fed
    // the states the script gives, the course is the open-loop one (closed_loop/replay.rs).
    let replaced = External { motion: ScriptedMotion::Replaced, ..External::named(["Ego"]) };
    let run = drive(&scenario(&ego_story()), &replaced, hold);
    // (The lane change ends a little before its 2 s: the held entity's speed is the speed
    // action's from 0, and while the lateral rate exceeds it esmini moves by speed·dt along the
    // straight line to the target, which can outrun the shape's clock — LatLaneChangeAction::Step.)
    assert!(event_time(&run, "OverAction", "end").is_some_and(|t| t > 2.5), "{:?}", event_time(&run, "OverAction", "end"));
    assert!(event_time(&run, "FasterAction", "end").is_none_or(|t| t > 2.9), "{:?}", event_time(&run, "FasterAction", "end"));
    assert!(!run.warnings.iter().any(|w| w.message.contains("driven from outside")), "{:?}", run.warnings);
    assert!(close(at(&run, "Ego", 5.0).x, 50.0, 1e-12) && close(at(&run, "Ego", 5.0).y, -1.75, 1e-12));
}

/// `text` with an ExternalController on Ego, activated at 1 s.
fn with_outside_driver(text: &str) -> String {
    let c = r#"<ObjectController><Controller name="outside"><Properties><Property name="esminiController" value="ExternalController"/></Properties></Controller></ObjectController></ScenarioObject>"#;
    text.replacen("</ScenarioObject>", c, 1)
}

#[test]
fn an_outside_drivers_controller_makes_its_entity_external_once_activated() {
    let activate = event(
        "Activate",
        "parallel",
        r#"<PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true" lateral="true"/></ControllerAction></PrivateAction>"#,
        &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0)),
    );
    let text = with_outside_driver(&scenario(&story("Ego", &activate)));
    let (scenario, net) = load(&text);
    let mut sim = Simulation::new(&scenario, Some(&net), &settings(), &RunControl::default(), &External::controllers()).expect("starts");
    let ext = sim.external();
    assert_eq!(ext.len(), 1);
    assert!(ext[0].name == "Ego" && !ext[0].active && matches!(&ext[0].source, engine::Source::Controller(c) if c.name == "outside"));
    // until 1 s the storyboard and the default controller drive it, and no input is asked for
    while sim.time() < 1.0 - 1e-9 {
        sim.step_with(&[]).expect("no input needed yet");
    }
    assert!(close(sim.state(EGO).expect("Ego").x, 60.0, 1e-9));
    // activated in the frame starting at 1 s: from the next on, an input is needed
    sim.step_with(&[]).expect("the activation frame holds it");
    assert!(sim.external()[0].active);
    assert!(matches!(sim.step_with(&[]), Err(engine::Error::Input(m)) if m.contains("no input for `Ego`")));
    sim.step_with(&[(EGO, Input::State(ExternalState::new(100.0, -1.75, 0.0, 3.0)))]).expect("steps");
    assert!(close(sim.state(EGO).expect("Ego").x, 100.0, 1e-12));
    // without the choice, the default controller drives it, with the warning of before
    let run = engine::simulate(&scenario, Some(&net), &settings()).expect("runs");
    assert!(close(at(&run, "Ego", 2.0).x, 70.0, 1e-9));
    assert!(run.warnings.iter().any(|w| w.message.contains("needs a driver or a process outside osc2cr")));
}

#[test]
fn the_same_inputs_give_the_same_run() {
    let input =
        |t: f64, _: &Simulation| vec![(EGO, Input::Driver(DriverInput { throttle: (t * 0.3).sin().abs(), brake: 0.0, steering: (t * 1.7).sin() * 0.2 }))];
    let a = drive(&scenario(&ego_story()), &External::named(["Ego"]), input);
    let b = drive(&scenario(&ego_story()), &External::named(["Ego"]), input);
    let boxes = vec![[1.5, 0.0, 0.9, 4.5, 2.0, 1.8]; 2];
    assert_eq!(a.trace.to_csv(&boxes), b.trace.to_csv(&boxes));
    assert_eq!(a.trace.events, b.trace.events);
}

/// Ego with an ExternalController activated in Init (after its teleport and speed), and at
/// 1 s a speed change and a lane change for it, at 4 s a teleport (`esmini_overrides_the_actions`).
fn overridden_by_an_outside_driver() -> String {
    // one Private per entity: esmini refuses a second one
    let ego = format!(
        r#"<Private entityRef="Ego"><PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>{}<PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true" lateral="true"/></ControllerAction></PrivateAction></Private>"#,
        lane_pos(50.0, -1),
        speed_action("step", "time", 0.0, 10.0)
    );
    let target = placed_in_one_private("Target", 200.0, -1, 5.0);
    let init = format!("{ego}{target}");
    let hop = event(
        "Hop",
        "parallel",
        &format!("<PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>", lane_pos(300.0, -1)),
        &trigger(&sim_time(4.0, "greaterOrEqual", "none", 0.0)),
    );
    let stories = story("Ego", &format!("{}{hop}", ego_events()));
    with_outside_driver(&xosc(&init, &stories, &stop_at(5.0)))
}

#[test]
#[ignore]
fn write_for_esmini() {
    std::fs::write(fixtures().join("outside_driver_overrides.xosc"), overridden_by_an_outside_driver()).expect("write");
}

/// esmini 3.6.0's run of `fixtures/outside_driver_overrides.xosc` (its ExternalController gets
/// no input, so esmini leaves Ego standing): the speed change ends at 1 s as it starts; the
/// lane change started at 1 s does not end by itself (2 s long, still running at 4 s) and is
/// ended at 4 s by the teleport, which moves nothing; Ego stays at s = 50 with speed 0 from
/// the first step on. Driven from outside and held, osc2cr's Ego does the same.
#[test]
fn esmini_overrides_the_actions_of_an_entity_driven_from_outside() {
    let text = std::fs::read_to_string(fixtures().join("outside_driver_overrides.xosc")).expect("fixture");
    let run = drive(&text, &External::controllers(), |_, _| vec![(EGO, Input::Hold)]);
    for (element, transition, time) in [
        ("FasterAction", "start", 1.0),
        ("FasterAction", "end", 1.0),
        ("OverAction", "start", 1.0),
        ("OverAction", "end", 4.0),
        ("HopAction", "start", 4.0),
        ("HopAction", "end", 4.0),
    ] {
        assert_eq!(event_time(&run, element, transition).map(|t| (t * 100.0).round() / 100.0), Some(time), "{element} {transition}");
    }
    assert_eq!(at(&run, "Ego", 0.0).speed, 10.0);
    for t in [0.01, 1.0, 2.0, 3.0, 4.0, 5.0] {
        let s = at(&run, "Ego", t);
        assert!(s.x == 50.0 && s.y == -1.75 && s.speed == 0.0, "at {t} s: {s:?}");
    }
    assert!(close(at(&run, "Target", 5.0).x, 225.0, 1e-9));
    // the Init's teleport and speed, done before the activation, are not said to be overridden
    let told = |element: &str| run.warnings.iter().any(|w| w.message.starts_with(&format!("{element} on `Ego`")));
    assert!(told("SpeedAction") && told("LaneChangeAction") && told("TeleportAction"), "{:?}", run.warnings);
    let init = |w: &&engine::Diagnostic| w.message.contains("driven from outside") && w.location.line == 21;
    assert_eq!(run.warnings.iter().filter(init).count(), 0, "{:?}", run.warnings);
}

/// Target, with an ACC (set speed 20 m/s, time gap 1 s) activated in the Init, follows Ego in
/// lane −1; Ego, driven from outside, drives at 15 m/s and stops hard at 3 s.
fn acc_behind_ego() -> String {
    let ego = placed_in_one_private("Ego", 100.0, -1, 15.0);
    let target = format!(
        r#"<Private entityRef="Target"><PrivateAction><TeleportAction>{}</TeleportAction></PrivateAction>{}<PrivateAction><ControllerAction><ActivateControllerAction longitudinal="true" lateral="false"/></ControllerAction></PrivateAction></Private>"#,
        lane_pos(60.0, -1),
        speed_action("step", "time", 0.0, 15.0)
    );
    let text = xosc(&format!("{ego}{target}"), "", &stop_at(10.0));
    let acc = r#"<ObjectController><Controller name="ACC"><Properties><Property name="esminiController" value="ACCController"/><Property name="timeGap" value="1"/><Property name="mode" value="override"/><Property name="setSpeed" value="20"/></Properties></Controller></ObjectController></ScenarioObject>"#;
    // the controller goes into Target's ScenarioObject (the second one)
    let at = text.match_indices("</ScenarioObject>").nth(1).map_or(text.len(), |(i, _)| i);
    format!("{}{acc}{}", &text[..at], &text[at + "</ScenarioObject>".len()..])
}

#[test]
fn an_acc_follows_the_entity_where_the_outside_puts_it() {
    // Ego's position from the outside: 15 m/s until 3 s, then braking at 8 m/s² to a stop
    let ego_at = |t: f64| {
        let (v0, a, t0) = (15.0, 8.0, 3.0);
        let stop = t0 + v0 / a;
        let (x, v) = if t <= t0 {
            (100.0 + v0 * t, v0)
        } else {
            let tt = t.min(stop) - t0;
            (100.0 + v0 * t0 + v0 * tt - 0.5 * a * tt * tt, (v0 - a * tt).max(0.0))
        };
        Input::State(ExternalState::new(x, -1.75, 0.0, v))
    };
    let run = drive(&acc_behind_ego(), &External::named(["Ego"]), |t, _| vec![(EGO, ego_at(t))]);
    // before the braking the ACC keeps its distance; after it, it has slowed and stopped behind Ego
    let (ego, target) = (at(&run, "Ego", 9.0), at(&run, "Target", 9.0));
    assert!(close(ego.x, 100.0 + 45.0 + 15.0 * 15.0 / 16.0, 1e-9), "{ego:?}");
    assert!(target.speed < 0.5, "the ACC car still drives at {} m/s", target.speed);
    assert!(target.x < ego.x - 4.5, "the ACC car at {} ran into Ego at {}", target.x, ego.x);
    // and it reacted to the outside's Ego: with Ego gone on at 15 m/s it would not have braked
    let cruising =
        drive(&acc_behind_ego(), &External::named(["Ego"]), |t, _| vec![(EGO, Input::State(ExternalState::new(100.0 + 15.0 * t, -1.75, 0.0, 15.0)))]);
    assert!(at(&cruising, "Target", 9.0).speed > 14.0, "{:?}", at(&cruising, "Target", 9.0));
}

//! Traffic signals: TrafficSignalStateAction sets a signal and TrafficSignalCondition starts
//! events on its state; the RoadNetwork's controllers are not run and a
//! TrafficSignalControllerAction changes nothing, as in esmini 3.6.0, which never reads
//! `RoadNetwork/TrafficSignals` and drops the action (`ScenarioReader::parseOSCGlobalAction`);
//! a TrafficSignalControllerCondition is left out of its group
//! (`conditions/ignored_value_conditions.rs`). The event times of
//! `controllers_and_their_action_change_no_signal` are esmini 3.6.0's on the same storyboard
//! (with the controller C1 alone) on a crossing whose signal 1 is a dynamic traffic light.

use crate::common::*;
use engine::{Run, Settings};

const RED: &str = "on;off;off";
const YELLOW: &str = "off;on;off";
const GREEN: &str = "off;off;on";

/// Controller C1 drives signal 1: go 3 s (green), wait 1 s (yellow), stop 4 s (red): an 8 s
/// cycle starting at 0. Controller C2 drives signal 2: walk 5 s ("on"), halt 3 s ("off"), with
/// its first phase 2 s after C1's.
const CONTROLLERS: &str = r#"<TrafficSignals>
<TrafficSignalController name="C1">
  <Phase name="go" duration="3"><TrafficSignalState trafficSignalId="1" state="off;off;on"/></Phase>
  <Phase name="wait" duration="1"><TrafficSignalState trafficSignalId="1" state="off;on;off"/></Phase>
  <Phase name="stop" duration="4"><TrafficSignalState trafficSignalId="1" state="on;off;off"/></Phase>
</TrafficSignalController>
<TrafficSignalController name="C2" reference="C1" delay="2">
  <Phase name="walk" duration="5"><TrafficSignalState trafficSignalId="2" state="on"/></Phase>
  <Phase name="halt" duration="3"><TrafficSignalState trafficSignalId="2" state="off"/></Phase>
</TrafficSignalController>
</TrafficSignals>"#;

fn run_signals(init: &str, stories: &str, controllers: bool, max_time: f64) -> Run {
    let mut text = xosc(init, stories, "");
    if controllers {
        text = text.replace(
            r#"<RoadNetwork><LogicFile filepath="straight.xodr"/></RoadNetwork>"#,
            &format!(r#"<RoadNetwork><LogicFile filepath="straight.xodr"/>{CONTROLLERS}</RoadNetwork>"#),
        );
        assert!(text.contains("TrafficSignals"), "the fixture's RoadNetwork element changed");
    }
    run_with(&text, &Settings { step: 0.01, max_time })
}

fn state_action(signal: &str, state: &str) -> String {
    format!(
        r#"<GlobalAction><InfrastructureAction><TrafficSignalAction><TrafficSignalStateAction name="{signal}" state="{state}"/></TrafficSignalAction></InfrastructureAction></GlobalAction>"#
    )
}

fn phase_action(controller: &str, phase: &str) -> String {
    format!(
        r#"<GlobalAction><InfrastructureAction><TrafficSignalAction><TrafficSignalControllerAction trafficSignalControllerRef="{controller}" phase="{phase}"/></TrafficSignalAction></InfrastructureAction></GlobalAction>"#
    )
}

fn signal_condition(signal: &str, state: &str, edge: &str, delay: f64) -> String {
    format!(
        r#"<Condition name="sig" delay="{delay}" conditionEdge="{edge}"><ByValueCondition><TrafficSignalCondition name="{signal}" state="{state}"/></ByValueCondition></Condition>"#
    )
}

fn phase_condition(controller: &str, phase: &str, edge: &str) -> String {
    format!(
        r#"<Condition name="ph" delay="0" conditionEdge="{edge}"><ByValueCondition><TrafficSignalControllerCondition trafficSignalControllerRef="{controller}" phase="{phase}"/></ByValueCondition></Condition>"#
    )
}

/// The (time, state) changes of `signal` in the trace.
fn changes(run: &Run, signal: &str) -> Vec<(f64, String)> {
    run.trace.signal_states.iter().filter(|s| s.signal == signal).map(|s| (s.time, s.state.clone())).collect()
}

fn assert_changes(run: &Run, signal: &str, want: &[(f64, &str)]) {
    let got = changes(run, signal);
    assert_eq!(got.len(), want.len(), "signal {signal}: {got:?}");
    for ((t, s), (wt, ws)) in got.iter().zip(want) {
        assert!(close(*t, *wt, 1e-6) && s == ws, "signal {signal}: got {got:?}, want {want:?}");
    }
}

#[test]
fn state_action_sets_a_signal_and_the_signal_condition_starts_an_event() {
    // Signal 1 starts red (Init); an event at t >= 2 s switches it to green. "Go" waits for
    // green with a 0.5 s delay: it sees the change in the same evaluation (it comes after
    // "Green"), so it starts at 2.5 s. "Never" waits for yellow, which never comes.
    let init = format!("{}{}", state_action("1", RED), teleport("Ego", 10.0, -1));
    let events = format!(
        "{}{}{}",
        event("Green", "parallel", &state_action("1", GREEN), &trigger(&sim_time(2.0, "greaterOrEqual", "none", 0.0))),
        event("Go", "parallel", &speed_action("step", "time", 0.0, 10.0), &trigger(&signal_condition("1", GREEN, "none", 0.5))),
        event("Never", "parallel", &speed_action("step", "time", 0.0, 1.0), &trigger(&signal_condition("1", YELLOW, "none", 0.0))),
    );
    let run = run_signals(&init, &story("Ego", &events), false, 5.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_changes(&run, "1", &[(0.0, RED), (2.0, GREEN)]);
    let go = event_time(&run, "Go", "start").expect("Go started");
    assert!(close(go, 2.5, 1e-6), "{go}");
    assert_eq!(event_time(&run, "Never", "start"), None);
    // Ego stands at x = 10 until 2.5 s, then drives at 10 m/s: at 4 s it has covered
    // 10 m/s x 1.5 s = 15 m (one step of tolerance).
    let x = at(&run, "Ego", 4.0).x;
    assert!(close(x, 25.0, 0.11), "{x}");
}

#[test]
fn controllers_and_their_action_change_no_signal() {
    // C1's first phase ("go", green) and C2's would be in force at 0 s; esmini runs neither, so
    // "Green" never starts. "Yellow" sets signal 1 at 3 s; "YellowSeen" waits 0.5 s more and
    // starts at 3.5 s. "Switch" (a TrafficSignalControllerAction to C1's "stop", red) starts
    // at 4 s and changes nothing: "Red" never starts. "BackToGo" waits for C1's phase, a
    // condition esmini drops: it never starts either.
    let events = [
        event("Green", "parallel", &speed_action("step", "time", 0.0, 2.0), &trigger(&signal_condition("1", GREEN, "none", 0.0))),
        event("Yellow", "parallel", &state_action("1", YELLOW), &trigger(&sim_time(3.0, "greaterOrEqual", "none", 0.0))),
        event("YellowSeen", "parallel", &speed_action("step", "time", 0.0, 4.0), &trigger(&signal_condition("1", YELLOW, "none", 0.5))),
        event("Switch", "parallel", &phase_action("C1", "stop"), &trigger(&sim_time(4.0, "greaterOrEqual", "none", 0.0))),
        event("Red", "parallel", &speed_action("step", "time", 0.0, 1.0), &trigger(&signal_condition("1", RED, "none", 0.0))),
        event("BackToGo", "parallel", &speed_action("step", "time", 0.0, 5.0), &trigger(&phase_condition("C1", "go", "rising"))),
    ]
    .concat();
    let run = run_signals(&teleport("Ego", 10.0, -1), &story("Ego", &events), true, 8.0);
    let text: Vec<&str> = run.warnings.iter().map(|w| w.message.as_str()).collect();
    assert_eq!(text.len(), 4, "{text:?}");
    for c in
        ["`C1` is not run", "`C2` is not run", "TrafficSignalControllerAction (controller `C1`, phase `stop`)", "TrafficSignalControllerCondition is left out"]
    {
        assert!(text.iter().any(|m| m.contains(c)), "{c}: {text:?}");
    }
    assert!(run.warnings.iter().all(|w| w.location.line > 0), "positioned");
    assert_changes(&run, "1", &[(3.0, YELLOW)]);
    assert_changes(&run, "2", &[]);
    for never in ["Green", "Red", "BackToGo"] {
        assert_eq!(event_time(&run, never, "start"), None, "{never}");
    }
    let seen = event_time(&run, "YellowSeen", "start").expect("YellowSeen started");
    assert!(close(seen, 3.5, 1e-6), "{seen}");
    let switch = event_time(&run, "Switch", "start").expect("Switch started");
    assert!(close(switch, 4.0, 1e-6), "{switch}");
    // Ego stood until 3.5 s, then drove at 4 m/s: 4 m/s x 1.5 s = 6 m at 5 s.
    let x = at(&run, "Ego", 5.0).x;
    assert!(close(x, 16.0, 0.05), "{x}");
}

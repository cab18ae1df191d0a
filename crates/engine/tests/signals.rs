//! Traffic signals: controllers of the RoadNetwork cycling through their phases (with a delay
//! to a reference controller), TrafficSignalStateAction, TrafficSignalControllerAction, and the
//! TrafficSignalCondition that starts events (a TrafficSignalControllerCondition is left out of its
//! group, as esmini 3.6.0 does: `conditions/ignored_value_conditions.rs`). Expected times
//! are worked out by hand from the phase durations; the trace's `signal_states` is checked.

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
fn controllers_cycle_through_their_phases_with_a_delay_to_their_reference() {
    // Steps are evaluated at 0, 0.01, ..., 19.99 s.
    let run = run_signals(&teleport("Ego", 10.0, -1), "", true, 20.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // C1: green at 0, yellow at 3, red at 4, then again every 8 s.
    assert_changes(&run, "1", &[(0.0, GREEN), (3.0, YELLOW), (4.0, RED), (8.0, GREEN), (11.0, YELLOW), (12.0, RED), (16.0, GREEN), (19.0, YELLOW)]);
    // C2's cycle starts at 2 s; at time 0 it is 6 s into the cycle before: halt ("off").
    // Then walk at 2, halt at 7, walk at 10, halt at 15, walk at 18.
    assert_changes(&run, "2", &[(0.0, "off"), (2.0, "on"), (7.0, "off"), (10.0, "on"), (15.0, "off"), (18.0, "on")]);
    // The trace lists the changes in time order.
    assert!(run.trace.signal_states.windows(2).all(|w| w[0].time <= w[1].time));
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
fn controller_action_switches_the_phase_and_a_phase_condition_is_ignored() {
    // At t >= 1 s C1 is put into "stop" (red): it then lasts its 4 s, so "go" comes back at
    // 5 s (not at 8 s as without the action), "wait" at 8 s, "stop" at 9 s. C2 is not
    // affected. "BackToGo" waits for C1 to enter "go": esmini 3.6.0 drops that condition, so
    // its group is empty and the event never starts (a warning says so).
    let events = format!(
        "{}{}",
        event("Switch", "parallel", &phase_action("C1", "stop"), &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0))),
        event("BackToGo", "parallel", &speed_action("step", "time", 0.0, 5.0), &trigger(&phase_condition("C1", "go", "rising"))),
    );
    let run = run_signals(&teleport("Ego", 10.0, -1), &story("Ego", &events), true, 10.0);
    assert_eq!(run.warnings.len(), 1, "{:?}", run.warnings);
    assert!(run.warnings[0].message.contains("TrafficSignalControllerCondition is left out"), "{:?}", run.warnings);
    assert_changes(&run, "1", &[(0.0, GREEN), (1.0, RED), (5.0, GREEN), (8.0, YELLOW), (9.0, RED)]);
    assert_changes(&run, "2", &[(0.0, "off"), (2.0, "on"), (7.0, "off")]);
    assert_eq!(event_time(&run, "BackToGo", "start"), None);
}

#[test]
fn unknown_controller_or_phase_is_a_warning() {
    let events = format!(
        "{}{}",
        event("NoSuchController", "parallel", &phase_action("C9", "go"), &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0))),
        event("NoSuchPhase", "parallel", &phase_action("C1", "dance"), &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0))),
    );
    let run = run_signals(&teleport("Ego", 10.0, -1), &story("Ego", &events), true, 2.0);
    let text: Vec<String> = run.warnings.iter().map(|w| w.message.clone()).collect();
    assert!(text.iter().any(|m| m.contains("`C9` is not defined")), "{text:?}");
    assert!(text.iter().any(|m| m.contains("no phase `dance`")), "{text:?}");
    assert!(run.warnings.iter().all(|w| w.location.line > 0), "positioned");
    // Nothing changed: C1 is still in "go" (it would turn yellow at 3 s, after the end).
    assert_changes(&run, "1", &[(0.0, GREEN)]);
}

//! A run's traffic-signal states become the cycle of the CommonRoad light made of that signal.
//! The road is the engine's straight fixture with one vehicle light (OpenDRIVE signal "7",
//! type 1000001) added; TrafficSignalStateActions at 1.0 s and 2.5 s (green → yellow → red)
//! and the stop at 4 s give the cycle by hand: the CommonRoad step is 0.1 s. A RoadNetwork
//! controller naming the light (which the run, as esmini 3.6.0, does not cycle) gives its
//! declared cycle to the light when no action sets it, and yields to the run's history otherwise.

use std::path::PathBuf;

use crate::common::{convert_and_clean, fresh_dir, global_event_at, one_maneuver_scenario, place, CAR};
use commonroad::TrafficLightColor;

fn set_light(t: f64, state: &str) -> String {
    let body = format!(
        r#"<InfrastructureAction><TrafficSignalAction><TrafficSignalStateAction name="7" state="{state}"/></TrafficSignalAction></InfrastructureAction>"#
    );
    global_event_at(&format!("e{t}"), &format!("a{t}"), t, &body)
}

/// The scenario; `actions`: whether TrafficSignalStateActions set light 7, `controller`: whether
/// the RoadNetwork declares CONTROLLER.
fn scenario(actions: bool, controller: bool) -> String {
    let ego = place("Ego", 10.0, -1, 10.0);
    let (init, events) = if actions {
        (format!("\n{}\n{ego}\n", set_light_now("off;off;on")), format!("{}{}", set_light(1.0, "off;on;off"), set_light(2.5, "on;off;off")))
    } else {
        (format!("\n{ego}\n"), KEEP_SPEED.to_string())
    };
    let xosc =
        one_maneuver_scenario("light", "light.xodr", &format!(r#"<ScenarioObject name="Ego">{CAR}</ScenarioObject>"#), &init, &events, "greaterOrEqual", 4.0);
    if controller {
        xosc.replacen("</RoadNetwork>", &format!("{CONTROLLER}</RoadNetwork>"), 1)
    } else {
        xosc
    }
}

/// An event that changes nothing (a maneuver needs one): Ego keeps its 10 m/s at 1 s.
const KEEP_SPEED: &str = r#"<Event name="keep" priority="parallel"><Action name="keep"><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" dynamicsDimension="time" value="0"/><SpeedActionTarget><AbsoluteTargetSpeed value="10"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Action>
<StartTrigger><ConditionGroup><Condition name="t" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="1" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger></Event>"#;

/// A controller starting 0.5 s in: light 7 green 2 s, yellow 0.5 s, red 3 s (the last phase
/// does not name it, so it stays red), then again.
const CONTROLLER: &str = r#"<TrafficSignals><TrafficSignalController name="crossing" delay="0.5">
<Phase name="go" duration="2"><TrafficSignalState trafficSignalId="7" state="off;off;on"/></Phase>
<Phase name="amber" duration="0.5"><TrafficSignalState trafficSignalId="7" state="off;on;off"/></Phase>
<Phase name="stop" duration="2"><TrafficSignalState trafficSignalId="7" state="on;off;off"/></Phase>
<Phase name="others_go" duration="1"/>
</TrafficSignalController></TrafficSignals>"#;

/// The Init's setting of light 7 to `state`.
fn set_light_now(state: &str) -> String {
    format!(
        r#"<GlobalAction><InfrastructureAction><TrafficSignalAction><TrafficSignalStateAction name="7" state="{state}"/></TrafficSignalAction></InfrastructureAction></GlobalAction>"#
    )
}

fn workdir(actions: bool, controller: bool) -> PathBuf {
    let dir = fresh_dir(&format!("light-cycles-{actions}-{controller}"));
    let fixture = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../engine/tests/fixtures/straight.xodr");
    let road = std::fs::read_to_string(fixture).expect("fixture road");
    let signal = r#"<signals><signal s="100" t="-4" id="7" name="light" dynamic="yes" orientation="+" zOffset="3" type="1000001" country="OpenDRIVE" subtype="-1" height="0.8" width="0.4"/></signals>
  </road>"#;
    std::fs::write(dir.join("light.xodr"), road.replacen("</road>", signal, 1)).expect("road written");
    std::fs::write(dir.join("light.xosc"), scenario(actions, controller)).expect("scenario written");
    dir
}

/// The light's cycle as (steps, colour), checking there is one light.
fn cycle(model: &convert::Model) -> Vec<(u64, TrafficLightColor)> {
    let lights = &model.scenario.network.traffic_lights;
    assert_eq!(lights.len(), 1, "{lights:#?}");
    lights[0].cycle.iter().map(|e| (e.duration.get(), e.color)).collect()
}

fn warnings_with(conversion: &convert::Conversion, needle: &str) -> Vec<String> {
    conversion.warnings.iter().map(|w| w.message.clone()).filter(|m| m.contains(needle)).collect()
}

#[test]
fn the_lights_cycle_is_the_runs_signal_history() {
    the_runs_history_is_the_cycle(false);
}

#[test]
fn a_declared_controller_yields_to_the_runs_history() {
    let conversion = the_runs_history_is_the_cycle(true);
    let shadowed = warnings_with(&conversion, "TrafficSignalController `crossing`: signal `7` was set by a TrafficSignalStateAction during the run");
    assert_eq!(shadowed.len(), 1, "{:#?}", conversion.warnings);
    assert!(warnings_with(&conversion, "its phases are written as the CommonRoad light cycle").is_empty(), "{:#?}", conversion.warnings);
}

#[test]
fn an_unset_light_takes_its_controllers_declared_cycle() {
    let (conversion, model) = convert_and_clean(&workdir(false, true), "light");
    // 2 s green, 0.5 s yellow, 2 s + 1 s red in steps of 0.1 s; the 0.5 s delay is the offset
    assert_eq!(cycle(&model), vec![(20, TrafficLightColor::Green), (5, TrafficLightColor::Yellow), (30, TrafficLightColor::Red)]);
    let light = &model.scenario.network.traffic_lights[0];
    assert_eq!((light.time_offset, light.active), (5, Some(true)));
    let used = warnings_with(&conversion, "TrafficSignalController `crossing`");
    assert_eq!(used.len(), 1, "{:#?}", conversion.warnings);
    assert!(
        used[0].contains(
            "esmini 3.6.0 does not run it, so no condition of the run saw its phases; its phases are written as the CommonRoad light cycle of signals 7"
        ),
        "{used:?}"
    );
}

/// Converts the scenario whose actions set light 7 (with or without the controller) and checks
/// the light's cycle is the run's history.
fn the_runs_history_is_the_cycle(controller: bool) -> convert::Conversion {
    let (conversion, model) = convert_and_clean(&workdir(true, controller), "light");
    let lights = &model.scenario.network.traffic_lights;
    assert_eq!(lights.len(), 1, "{lights:#?}");
    let got: Vec<(u64, TrafficLightColor)> = lights[0].cycle.iter().map(|e| (e.duration.get(), e.color)).collect();
    // green steps 0–9, yellow 10–24, red from step 25 to the last step of the scenario
    let duration = conversion.facts.duration_s.expect("duration");
    let last = (duration / 0.1).round() as u64;
    assert!((3.9..=4.1).contains(&duration), "{duration}");
    assert_eq!(got, vec![(10, TrafficLightColor::Green), (15, TrafficLightColor::Yellow), (last + 1 - 25, TrafficLightColor::Red)]);
    assert_eq!(lights[0].time_offset, 0);
    conversion
}

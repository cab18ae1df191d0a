//! A run's traffic-signal states become the cycle of the CommonRoad light made of that signal.
//! The road is the engine's straight fixture with one vehicle light (OpenDRIVE signal "7",
//! type 1000001) added; TrafficSignalStateActions at 1.0 s and 2.5 s (green → yellow → red)
//! and the stop at 4 s give the cycle by hand: the CommonRoad step is 0.1 s.

use std::path::PathBuf;

use crate::common::{convert_and_clean, fresh_dir, global_event_at, one_maneuver_scenario, place, CAR};
use commonroad::TrafficLightColor;

fn set_light(t: f64, state: &str) -> String {
    let body = format!(
        r#"<InfrastructureAction><TrafficSignalAction><TrafficSignalStateAction name="7" state="{state}"/></TrafficSignalAction></InfrastructureAction>"#
    );
    global_event_at(&format!("e{t}"), &format!("a{t}"), t, &body)
}

fn scenario() -> String {
    let init = format!("\n{}\n{}\n", set_light_now("off;off;on"), place("Ego", 10.0, -1, 10.0));
    let events = format!("{}{}", set_light(1.0, "off;on;off"), set_light(2.5, "on;off;off"));
    one_maneuver_scenario("light", "light.xodr", &format!(r#"<ScenarioObject name="Ego">{CAR}</ScenarioObject>"#), &init, &events, "greaterOrEqual", 4.0)
}

/// The Init's setting of light 7 to `state`.
fn set_light_now(state: &str) -> String {
    format!(
        r#"<GlobalAction><InfrastructureAction><TrafficSignalAction><TrafficSignalStateAction name="7" state="{state}"/></TrafficSignalAction></InfrastructureAction></GlobalAction>"#
    )
}

fn workdir() -> PathBuf {
    let dir = fresh_dir("light-cycles");
    let fixture = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../engine/tests/fixtures/straight.xodr");
    let road = std::fs::read_to_string(fixture).expect("fixture road");
    let signal = r#"<signals><signal s="100" t="-4" id="7" name="light" dynamic="yes" orientation="+" zOffset="3" type="1000001" country="OpenDRIVE" subtype="-1" height="0.8" width="0.4"/></signals>
  </road>"#;
    std::fs::write(dir.join("light.xodr"), road.replacen("</road>", signal, 1)).expect("road written");
    std::fs::write(dir.join("light.xosc"), scenario()).expect("scenario written");
    dir
}

#[test]
fn the_lights_cycle_is_the_runs_signal_history() {
    let (conversion, model) = convert_and_clean(&workdir(), "light");
    let lights = &model.scenario.network.traffic_lights;
    assert_eq!(lights.len(), 1, "{lights:#?}");
    let got: Vec<(u64, TrafficLightColor)> = lights[0].cycle.iter().map(|e| (e.duration.get(), e.color)).collect();
    // green steps 0–9, yellow 10–24, red from step 25 to the last step of the scenario
    let duration = conversion.facts.duration_s.expect("duration");
    let last = (duration / 0.1).round() as u64;
    assert!((3.9..=4.1).contains(&duration), "{duration}");
    assert_eq!(got, vec![(10, TrafficLightColor::Green), (15, TrafficLightColor::Yellow), (last + 1 - 25, TrafficLightColor::Red)]);
    assert_eq!(lights[0].time_offset, 0);
}

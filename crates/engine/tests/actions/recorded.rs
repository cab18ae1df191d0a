//! What a run records without simulating: LightStateActions (Run::lights, with a warning that
//! CommonRoad 2020a cannot carry lights) and EnvironmentActions in Init and in the story
//! (Run::environment, no warning). Times follow the frame order: Init at 0 s, a story action
//! at the storyboard time its trigger held.

use crate::common::*;
use openscenario::{LightMode, LightType};

fn light(kind: &str, mode: &str, extra: &str) -> String {
    format!(
        r#"<PrivateAction><AppearanceAction><LightStateAction transitionTime="0.5"><LightType><VehicleLight vehicleLightType="{kind}"/></LightType><LightState mode="{mode}"{extra}/></LightStateAction></AppearanceAction></PrivateAction>"#
    )
}

fn environment(name: &str, wetness: &str) -> String {
    format!(
        r#"<GlobalAction><EnvironmentAction><Environment name="{name}"><TimeOfDay animation="false" dateTime="2024-06-01T21:30:00"/><Weather><Precipitation precipitationType="rain" precipitationIntensity="2.5"/></Weather><RoadCondition frictionScaleFactor="0.6" wetness="{wetness}"/></Environment></EnvironmentAction></GlobalAction>"#
    )
}

#[test]
fn light_states_are_kept_with_their_time_and_a_warning() {
    let init = format!("{}{}", teleport("Ego", 100.0, -1), init_speed("Ego", "step", "time", 0.0, 10.0));
    let events = format!(
        "{}{}",
        event("Low", "parallel", &light("lowBeam", "on", ""), &trigger(&sim_time(1.0, "greaterOrEqual", "none", 0.0))),
        event(
            "Blink",
            "parallel",
            &light("indicatorLeft", "flashing", r#" flashingOnDuration="0.4" flashingOffDuration="0.6""#),
            &trigger(&sim_time(2.0, "greaterOrEqual", "none", 0.0))
        ),
    );
    let r = run(&xosc(&init, &story("Ego", &events), &stop_at(3.0)));
    assert_eq!(r.lights.len(), 2, "{:?}", r.lights);
    let (low, blink) = (&r.lights[0], &r.lights[1]);
    assert!(close(low.time, 1.0, 1e-9) && low.entity == "Ego" && low.light == LightType::Vehicle("lowBeam".into()));
    assert_eq!(low.state.mode, LightMode::On);
    assert_eq!(low.transition_time, Some(0.5));
    assert!(close(blink.time, 2.0, 1e-9) && blink.light == LightType::Vehicle("indicatorLeft".into()));
    assert_eq!(blink.state.mode, LightMode::Flashing);
    assert_eq!((blink.state.flashing_on_duration, blink.state.flashing_off_duration), (Some(0.4), Some(0.6)));
    let light_warnings: Vec<_> = r.warnings.iter().filter(|w| w.message.contains("LightStateAction")).collect();
    assert_eq!(light_warnings.len(), 2, "one warning per action: {:?}", r.warnings);
    assert!(light_warnings.iter().all(|w| w.message.contains("CommonRoad 2020a")));
    // The motion is not affected: 100 + 10 · 3 = 130 m.
    assert!(close(at(&r, "Ego", 3.0).x, 130.0, 1e-9));
}

#[test]
fn environments_are_kept_from_init_and_story() {
    let init = format!("{}{}", environment("Dusk", "wetWithPuddles"), teleport("Ego", 100.0, -1));
    let events = event("Dry", "parallel", &environment("Night", "dry"), &trigger(&sim_time(1.5, "greaterOrEqual", "none", 0.0)));
    let r = run(&xosc(&init, &story("Ego", &events), &stop_at(2.0)));
    let got: Vec<(f64, &str)> = r.environment.iter().map(|e| (e.time, e.environment.name.as_str())).collect();
    assert_eq!(got.len(), 2, "{got:?}");
    assert!(close(got[0].0, 0.0, 1e-12) && got[0].1 == "Dusk", "{got:?}");
    assert!(close(got[1].0, 1.5, 1e-9) && got[1].1 == "Night", "{got:?}");
    let env = &r.environment[0].environment;
    assert_eq!(env.time_of_day.as_ref().map(|t| t.date_time.as_str()), Some("2024-06-01T21:30:00"));
    assert_eq!(env.road_condition.as_ref().map(|c| c.friction_scale_factor), Some(0.6));
    assert_eq!(env.weather.as_ref().and_then(|w| w.precipitation.as_ref()).and_then(|p| p.intensity), Some(2.5));
    assert!(r.warnings.iter().all(|w| !w.message.contains("EnvironmentAction")), "{:?}", r.warnings);
}

//! Light cycles come back: `convert(export(S))` gives every traffic light of S the colours S's
//! cycle gives it, step by step over two of its cycles (the export writes each cycle as a
//! TrafficSignalController, which the run does not cycle, as esmini 3.6.0; the conversion writes
//! a controller's declared phases as the light's cycle). On the CommonRoad scenarios of
//! `../shared/commonroad-scenarios` that have traffic lights. The map round trip keeps a light's
//! id as its OpenDRIVE signal id, so lights are matched by id.

use std::path::Path;

use commonroad::{TrafficLight, TrafficLightColor};

use crate::common::{commonroad_scenarios, export_batch, fresh_dir, short};

/// The colour of `light` at step `t`, as commonroad-io reads a cycle: the cycle's colour at
/// (t − offset) mod its length; an inactive light is dark.
fn colour_at(light: &TrafficLight, t: u64) -> TrafficLightColor {
    let total: u64 = light.cycle.iter().map(|e| e.duration.get()).sum();
    if light.active == Some(false) || total == 0 {
        return TrafficLightColor::Inactive;
    }
    let mut at = (t + total - light.time_offset % total) % total;
    for e in &light.cycle {
        if at < e.duration.get() {
            return e.color;
        }
        at -= e.duration.get();
    }
    TrafficLightColor::Inactive
}

/// The differences between S's lights and those of convert(export(S)) (S's file `input`), or
/// why there is nothing to compare.
fn light_differences(input: &Path, xosc: &Path) -> Result<Vec<String>, String> {
    let source = export::read_source(input)?;
    let s = &source.scenario;
    let name = export::scenario_name(input);
    let request = convert::Request { source: "light cycles back".into(), ..convert::Request::named(xosc, &name) }.keeping_model();
    let options = convert::ConvertOptions { dt: s.header.time_step_size, ..Default::default() };
    let (conversion, model) = convert::convert(&request, &options);
    let Some(model) = model else {
        // as in forward_again: a scenario without a planning problem has no ego to convert with
        return Err(format!("convert fails: {:?}", conversion.result.err().map(|f| f.message)));
    };
    let back = &model.scenario.network.traffic_lights;
    // the map round trip renumbers lights (and S's may have no position), so each light is
    // known by its colours: the lights of both sides, as step-by-step sequences, are the same
    let horizon = 2 * s.network.traffic_lights.iter().map(|l| l.cycle.iter().map(|e| e.duration.get()).sum::<u64>()).max().unwrap_or(1);
    let colours = |lights: &[TrafficLight]| {
        let mut v: Vec<Vec<TrafficLightColor>> = lights.iter().map(|l| (0..horizon).map(|t| colour_at(l, t)).collect()).collect();
        v.sort_by_key(|c| format!("{c:?}"));
        v
    };
    let (want, got) = (colours(&s.network.traffic_lights), colours(back));
    if want == got {
        return Ok(Vec::new());
    }
    let missing: Vec<String> = s
        .network
        .traffic_lights
        .iter()
        .filter(|l| !got.contains(&(0..horizon).map(|t| colour_at(l, t)).collect()))
        .map(|l| format!("light {} {:?}", l.id.get(), l.cycle))
        .collect();
    Ok(vec![format!("{} lights → {}; not given back over {horizon} steps: {}", want.len(), got.len(), missing.join(", "))])
}

#[test]
fn convert_of_export_gives_the_light_cycles_back() {
    let inputs: Vec<_> =
        commonroad_scenarios().into_iter().filter(|p| export::read_source(p).is_ok_and(|s| !s.scenario.network.traffic_lights.is_empty())).collect();
    if inputs.is_empty() {
        return;
    }
    let root = fresh_dir("light-cycles-back");
    let exported = export_batch(&inputs, &root, &export::ExportOptions { play_to_end: true, ..Default::default() });
    let mut compared = 0;
    let mut skipped = Vec::new();
    let mut failed = Vec::new();
    for (input, xosc) in &exported {
        match xosc.as_ref().map_err(String::clone).and_then(|x| light_differences(input, x)) {
            Ok(d) => {
                compared += 1;
                if !d.is_empty() {
                    failed.push(format!("{}: {}", short(input), d.join("; ")));
                }
            }
            Err(why) => skipped.push(format!("{}: {why}", short(input))),
        }
    }
    eprintln!("light cycles back: {compared} of {} scenarios with lights compared, {} differ", inputs.len(), failed.len());
    for s in &skipped {
        eprintln!("  skipped {s}");
    }
    assert!(compared > 0, "no scenario with traffic lights was compared: {skipped:#?}");
    assert!(failed.is_empty(), "{failed:#?}");
}

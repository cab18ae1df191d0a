//! The two stages other crates own, behind one narrow call each: OpenDRIVE → lanelets (`map`)
//! and the storyboard run (`engine`).

use std::collections::{BTreeMap, BTreeSet};

use commonroad::{LaneletNetwork, Tag, TrafficLightId};
use engine::{Settings, Trace};

use crate::options::ConvertOptions;

/// The lanelet network of a road network.
pub struct MapOutput {
    pub network: LaneletNetwork,
    /// Tags that follow from the network (road class, lane count, intersection, …).
    pub tags: BTreeSet<Tag>,
    /// The traffic light made of each OpenDRIVE signal id.
    pub light_of_signal: BTreeMap<String, TrafficLightId>,
    pub warnings: Vec<String>,
}

/// What the engine returns.
pub(crate) struct EngineOutput {
    pub trace: Trace,
    pub warnings: Vec<String>,
}

/// Lanelets of `road`. Signals that name no country are read as the benchmark's country when
/// one is given (ZAM: the map converter's default).
pub(crate) fn run_map(road: &opendrive::RoadNetwork, options: &ConvertOptions) -> MapOutput {
    let result = map::convert(road, &map_options(&options.country, options.map_tolerance));
    MapOutput {
        tags: map::derived_tags(&result.network),
        // the map converter's warnings have always said so
        warnings: result.warnings.iter().map(|w| w.labelled("warning").to_string()).collect(),
        light_of_signal: result.light_of_signal,
        network: result.network,
    }
}

/// Runs the storyboard.
pub(crate) fn run_engine(
    scenario: &openscenario::Scenario,
    road: Option<&opendrive::RoadNetwork>,
    options: &ConvertOptions,
) -> Result<EngineOutput, engine::Error> {
    let settings = Settings { step: options.step, max_time: options.max_time };
    let control = engine::RunControl { seed: options.engine_seed, deadline: options.deadline };
    let run = engine::simulate_with(scenario, road, &settings, &control)?;
    Ok(EngineOutput { trace: run.trace, warnings: run.warnings.iter().map(ToString::to_string).collect() })
}

/// The map converter's options for a scenario of `country` (the benchmark id's code, `ZAM` or
/// ISO 3166 alpha-3), which is also the country of the signals that name none (ZAM: the map
/// converter's default, the German catalogue of the OpenDRIVE annex), and a bound `tolerance`
/// (`None`: the converter's default). `osc2cr map` and `convert` share it, so that `--country`
/// means one thing in both.
pub fn map_options(country: &str, tolerance: Option<f64>) -> map::MapOptions {
    let defaults = map::MapOptions::default();
    map::MapOptions { default_country: (country != "ZAM").then(|| country.to_string()), tolerance: tolerance.unwrap_or(defaults.tolerance), ..defaults }
}

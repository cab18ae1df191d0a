//! `map` — OpenDRIVE road network → CommonRoad lanelet network.
//!
//! It owns the lanelet conversion: one lanelet per kept lane per lane section, bounds
//! sampled adaptively within a tolerance of the exact borders (f64 geometry of the
//! `opendrive` crate), driving direction from lane side and traffic rule, predecessors and
//! successors across sections, roads and junctions, adjacency, lanelet types, line markings,
//! traffic signs / lights / stop lines from signals, intersections from junctions, and the
//! scenario tags a map implies. The map stays in the OpenDRIVE frame (no re-projection).
//!
//! It must not know OpenSCENARIO, the engine or how a full scenario is assembled; it builds
//! `commonroad` model values and never writes files itself.
//!
//! Module map: [`options`] (settings, result), `lane_class` (lane/road type → lanelet types),
//! `borders` + `sampling` (border t values, adaptive stations), `build` (lanelets),
//! `topology` (successors), `adjacency`, `markings`, `signals` (signs, lights, stop lines),
//! [`intersections`], [`tags`], [`map_scenario`] (a map-only scenario for `osc2cr map`).

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod adjacency;
mod borders;
mod build;
pub mod intersections;
pub mod lane_class;
pub mod map_scenario;
pub mod markings;
pub mod options;
mod sampling;
pub mod signals;
pub mod tags;
mod topology;
mod warn;

pub use map_scenario::{map_scenario, map_scenario_id, map_scenario_id_in};
pub use options::{LaneletOrigin, MapOptions, MapResult};
pub use sampling::MAX_STATIONS;
pub use tags::derived_tags;

use commonroad::{IdAllocator, LaneletNetwork};
use opendrive::RoadNetwork;

/// Converts a road network; lanelet ids start at 1, then signs, lights, intersections.
pub fn convert(net: &RoadNetwork, opts: &MapOptions) -> MapResult {
    let mut ids = IdAllocator::new();
    convert_with_ids(net, opts, &mut ids)
}

/// [`convert`] with ids taken from `ids` (to share one id space with other elements).
pub fn convert_with_ids(net: &RoadNetwork, opts: &MapOptions, ids: &mut IdAllocator) -> MapResult {
    let mut warn = warn::WarningSink::default();
    let mut built = build::build_lanelets(net, opts.tolerance, ids, &mut warn);
    topology::link(net, &mut built, &mut warn);
    adjacency::adjacent(net, &mut built);
    let (traffic_signs, traffic_lights, light_of_signal) = signals::convert_signals(net, &mut built, opts, ids, &mut warn);
    let intersections = intersections::intersections(net, &built, ids);
    let lanelet_of = built.index_of.iter().filter_map(|(k, &i)| built.lanelets.get(i).map(|l| (*k, l.id))).collect();
    MapResult {
        network: LaneletNetwork { lanelets: built.lanelets, traffic_signs, traffic_lights, intersections },
        origins: built.origins,
        lanelet_of,
        light_of_signal,
        warnings: warn.finish(),
    }
}

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

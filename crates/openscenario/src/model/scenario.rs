//! The top level: header, road network, entities, storyboard, parameters.

use super::{Entity, EntitySelection, Origin, Storyboard};
use crate::params::ParameterDeclaration;
use serde::Serialize;
use std::path::PathBuf;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scenario {
    /// The scenario file (absolute).
    pub path: PathBuf,
    pub header: FileHeader,
    /// Global parameter declarations with their final values (after overrides).
    pub parameters: Vec<ParameterDeclaration>,
    /// Global variable declarations (OpenSCENARIO 1.2+), initial values.
    pub variables: Vec<ParameterDeclaration>,
    pub road_network: RoadNetwork,
    pub entities: Vec<Entity>,
    pub entity_selections: Vec<EntitySelection>,
    pub storyboard: Storyboard,
    /// Where each name that refers to something else was written (entities, roads, lanes,
    /// storyboard elements, …), in reading order: a check that finds such a name refers to
    /// nothing reports it at its own attribute ([`Scenario::reference_site`]).
    #[serde(skip)]
    pub reference_sites: Vec<crate::references::ReferenceSite>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FileHeader {
    pub rev_major: u32,
    pub rev_minor: u32,
    pub date: String,
    pub description: String,
    pub author: String,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RoadNetwork {
    /// The OpenDRIVE file, resolved relative to the scenario file (not loaded here).
    pub logic_file: Option<PathBuf>,
    /// Where the scenario names it (its `<LogicFile>`), for messages about the file.
    #[serde(skip)]
    pub logic_file_at: Option<crate::Location>,
    pub scene_graph_file: Option<PathBuf>,
    pub traffic_signal_controllers: Vec<TrafficSignalController>,
    /// UsedArea corner points (x, y) in world coordinates.
    pub used_area: Vec<(f64, f64)>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrafficSignalController {
    pub name: String,
    pub delay: Option<f64>,
    pub reference: Option<String>,
    pub phases: Vec<Phase>,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Phase {
    pub name: String,
    pub duration: f64,
    /// (trafficSignalId, state)
    pub states: Vec<(String, String)>,
    /// TrafficSignalGroupState (1.2+).
    pub group_state: Option<String>,
}

impl Scenario {
    /// Where the attribute `attribute` whose value `matches` was written within the element at
    /// `within` (an action, condition, maneuver group, route, …, that holds it): the first such
    /// site at or after the element's start in its file, else `within` itself.
    pub fn reference_site<'a>(&'a self, within: &'a crate::Location, attribute: &str, matches: impl Fn(&str) -> bool) -> &'a crate::Location {
        self.reference_sites
            .iter()
            .filter(|s| s.attribute == attribute && s.location.file == within.file && (s.location.line, s.location.col) >= (within.line, within.col))
            .filter(|s| matches(&s.value))
            .min_by_key(|s| (s.location.line, s.location.col))
            .map_or(within, |s| &s.location)
    }

    /// The entity named `name`.
    pub fn entity(&self, name: &str) -> Option<&super::Entity> {
        self.entities.iter().find(|e| e.name == name)
    }

    /// The global parameter named `name` (a leading `$` is ignored).
    pub fn parameter(&self, name: &str) -> Option<&ParameterDeclaration> {
        let name = name.trim_start_matches('$');
        self.parameters.iter().find(|p| p.name == name)
    }
}

//! The storyboard tree.

use super::{Action, Origin, Trigger};
use crate::params::ParameterDeclaration;
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Storyboard {
    pub init: Init,
    pub stories: Vec<Story>,
    /// None when absent (the run ends at the maximum time or when all stories complete).
    pub stop_trigger: Option<Trigger>,
}

impl Storyboard {
    /// Every Event of every story, act, maneuver group and maneuver, in document order.
    pub fn events(&self) -> impl Iterator<Item = &Event> {
        self.stories.iter().flat_map(|s| &s.acts).flat_map(|a| &a.maneuver_groups).flat_map(|g| &g.maneuvers).flat_map(|m| &m.events)
    }
}

#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Init {
    pub global: Vec<Action>,
    pub private: Vec<InitPrivate>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InitPrivate {
    pub entity: String,
    pub actions: Vec<Action>,
    /// The `Private` element.
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Story {
    pub name: String,
    pub parameters: Vec<ParameterDeclaration>,
    pub acts: Vec<Act>,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Act {
    pub name: String,
    pub maneuver_groups: Vec<ManeuverGroup>,
    /// None when the element is absent (esmini then treats the act as started at once).
    pub start_trigger: Option<Trigger>,
    pub stop_trigger: Option<Trigger>,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ManeuverGroup {
    pub name: String,
    pub maximum_execution_count: u32,
    pub select_triggering_entities: bool,
    pub actors: Vec<String>,
    pub maneuvers: Vec<Maneuver>,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Maneuver {
    pub name: String,
    pub parameters: Vec<ParameterDeclaration>,
    pub events: Vec<Event>,
    pub origin: Origin,
}

crate::xml_enum! {
    Priority {
        /// `overwrite` (1.0) is read as `override`.
        Override = "override" | "overwrite",
        Skip = "skip",
        Parallel = "parallel",
    }
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Event {
    pub name: String,
    pub priority: Priority,
    pub maximum_execution_count: u32,
    pub actions: Vec<Action>,
    pub start_trigger: Option<Trigger>,
    pub origin: Origin,
}

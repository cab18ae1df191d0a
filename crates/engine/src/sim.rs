//! The state of one run: entities, the storyboard's nodes, triggers and actions, controllers,
//! parameters, the event log and the warnings — everything a frame reads and changes, and
//! nothing of how: it imports only data (the `state` modules of `actions`, `conditions`,
//! `controllers`, `ghost`, and the plain data modules). `setup.rs` builds it; the behaviours
//! (`storyboard`, `conditions`, `actions`, `controllers`, `motion`, `external`, …) change it;
//! `run.rs` orders them into frames.

use crate::actions::state::ActionSlot;
use crate::conditions::state::TriggerRt;
use crate::entities::Entity;
use crate::storyboard::{Node, State, Transition};
use crate::trace::StoryboardEvent;
use crate::values::Values;
use crate::Diagnostic;
use opendrive::RoadNetwork;
use openscenario::Scenario;

pub(crate) struct Sim<'a> {
    pub scenario: &'a Scenario,
    pub net: Option<&'a RoadNetwork>,
    pub dt: f64,
    /// Simulation time of the storyboard step in progress, s.
    pub time: f64,
    /// esmini's `simulationTime_`, which `ScenarioEngine::step` accumulates by adding the step
    /// each frame (and a ghost restart rewinds): `time` is the step count times the step, and
    /// the two differ in the last bits. The stand-still and off-road durations are measured on
    /// this one, as esmini measures them, because its strict comparison decides on those bits.
    pub clock: f64,
    pub entities: Vec<Entity>,
    pub nodes: Vec<Node>,
    pub triggers: Vec<TriggerRt<'a>>,
    pub actions: Vec<ActionSlot<'a>>,
    /// Action slots of the Init section, in document order (global first, as esmini).
    pub init_actions: Vec<usize>,
    pub params: Values,
    pub vars: Values,
    pub events: Vec<StoryboardEvent>,
    /// Every state change (node, new state, transition), read by StoryboardElementState conditions.
    pub state_log: Vec<(usize, State, Transition)>,
    pub warnings: Vec<Diagnostic>,
    /// Every controller assigned to an entity, in the order esmini steps them
    /// (`controllers/step_order.rs`); an entity without one has the default controller.
    pub controllers: Vec<crate::controllers::state::ControllerSlot>,
    /// Some entity has a modelled controller: without one the controller steps of a frame are
    /// skipped outright (most scenarios have none).
    pub any_controller: bool,
    /// How many assignments were made (orders an entity's controllers by their last one).
    pub assignments: u64,
    /// Who pulls whom (actions/trailer.rs).
    pub trailers: crate::actions::trailer::state::Trailers,
    /// The ghost of a FollowGhost / FollowReference controller (ghost/).
    pub ghost: Option<crate::ghost::state::Ghost>,
    /// Maneuver groups with `selectTriggeringEntities` (storyboard/select_triggering.rs).
    pub triggering_actors: Vec<crate::storyboard::tree::TriggeringActors>,
    /// Light states and environments asked for (recorded.rs).
    pub lights: Vec<crate::recorded::LightChange>,
    pub environment: Vec<crate::recorded::EnvironmentChange>,
    /// Traffic-signal states (signals.rs).
    pub signals: crate::signals::Signals,
    /// esmini's global random generator (esmini_random.rs), seeded by `simulate_seeded`.
    pub random: crate::esmini_random::EsminiRandom,
    /// Which entities the caller drives (external/), and each one's state.
    pub external_choice: crate::external::External,
    pub external: Vec<Option<crate::external::driven::Driven>>,
    /// When the NaturalDriver may measure each pair of entities again
    /// (controllers/natural_driver/distance_cache.rs).
    pub nd_distances: crate::controllers::natural_driver::state::DistanceCache,
}

impl<'a> Sim<'a> {
    pub(crate) fn entity_index(&self, name: &str) -> Option<usize> {
        self.entities.iter().position(|e| e.name == name)
    }

    /// The entity a reference of action `slot` names: the ghost where the action was handed
    /// over to it and names the ghost's entity (ScenarioEngine::SetupGhost's ReplaceObjectRefs:
    /// a relative lane, lane offset or speed target, a speed profile's entity).
    pub(crate) fn action_ref_index(&self, slot: usize, name: &str) -> Option<usize> {
        let i = self.entity_index(name)?;
        match self.actions.get(slot).and_then(|a| a.ghost_refs) {
            Some((owner, ghost)) if owner == i => Some(ghost),
            _ => Some(i),
        }
    }

    /// `pos` as action `slot` reads it: where the action was handed over to a ghost and the
    /// position is relative to the ghost's entity, relative to the ghost (TeleportAction::
    /// ReplaceObjectRefs, Position::ReplaceObjectRefs); `None` where it reads `pos` as it is.
    pub(crate) fn action_ref_position(&self, slot: usize, pos: &openscenario::Position) -> Option<openscenario::Position> {
        let (owner, ghost) = self.actions.get(slot)?.ghost_refs?;
        let owner_name = &self.entities.get(owner)?.name;
        let ghost_name = &self.entities.get(ghost)?.name;
        if pos.reference_entity() != Some(owner_name.as_str()) {
            return None;
        }
        let mut out = pos.clone();
        if let openscenario::Position::RelativeWorld { entity, .. }
        | openscenario::Position::RelativeObject { entity, .. }
        | openscenario::Position::RelativeRoad { entity, .. }
        | openscenario::Position::RelativeLane { entity, .. } = &mut out
        {
            entity.clone_from(ghost_name);
        }
        Some(out)
    }

    /// Record a state change of node `id` (event log + condition log).
    pub(crate) fn set_state(&mut self, id: usize, transition: Transition, to: State) {
        let Some(n) = self.nodes.get_mut(id) else { return };
        let from = n.state;
        if from == to && transition != Transition::Start {
            return;
        }
        n.state = to;
        self.events.push(StoryboardEvent {
            time: self.time,
            element: n.name.clone(),
            from: from.name().to_string(),
            transition: transition.name().to_string(),
            to: to.name().to_string(),
        });
        self.state_log.push((id, to, transition));
    }
}

//! `selectTriggeringEntities="true"` on a maneuver group's Actors: when the group starts, its
//! actors are the listed ones plus the entities that made the start trigger of its Act true
//! (the OpenSCENARIO rule; esmini 3.6 ignores the attribute and lets the listed actors act,
//! which is what this gives whenever the Act's start trigger holds no entity condition).

use super::Kind;
use crate::sim::Sim;

impl Sim<'_> {
    /// Set the actors of maneuver group `mg` (just started) if it selects triggering entities.
    pub(crate) fn select_triggering_actors(&mut self, mg: usize) {
        let Some(k) = self.triggering_actors.iter().position(|t| t.group == mg) else { return };
        let act = self.nodes.get(mg).and_then(|n| n.parent).filter(|&a| self.nodes[a].kind == Kind::Act);
        let from_trigger =
            act.and_then(|a| self.nodes[a].start_trigger).and_then(|t| self.triggers.get(t)).map(|t| t.triggering_entities()).unwrap_or_default();
        let mut actors = self.triggering_actors[k].listed.clone();
        for e in from_trigger {
            if !actors.contains(&e) {
                actors.push(e);
            }
        }
        for i in 0..self.triggering_actors[k].slots.len() {
            let slot = self.triggering_actors[k].slots[i];
            if let Some(s) = self.actions.get_mut(slot) {
                s.actors.clone_from(&actors);
            }
        }
    }
}

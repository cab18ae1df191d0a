//! AddEntityAction and DeleteEntityAction, as esmini runs them: every declared entity exists
//! from the start; deleting one takes it out of the simulation (no trace rows, no default
//! controller, no driver model; entity conditions skip it) together with the trailers it
//! tows; adding it back puts it at the action's position with the speed it had, its trailers
//! straight behind it. Adding an entity that exists, or deleting one that does not, is skipped
//! with a warning (esmini logs the same and skips).
//!
//! What esmini leaves open we decide: the running actions of a deleted entity end (there is
//! nothing left for them to move), and a private action started on a deleted entity does
//! nothing (warning).

use crate::sim::Sim;
use openscenario::Position;

/// Longest tow chain followed (hostile input).
const MAX_CHAIN: usize = 100;

impl<'a> Sim<'a> {
    pub(super) fn add_entity(&mut self, slot: usize, name: &str, pos: &Position) {
        let Some(e) = self.entity_index(name) else {
            self.warn_action(slot, format!("AddEntityAction: unknown entity `{name}`; skipped"));
            return;
        };
        if self.entities[e].active {
            self.warn_action(slot, format!("AddEntityAction: entity `{name}` already exists; skipped"));
            return;
        }
        for t in self.tow_chain(e) {
            if let Some(en) = self.entities.get_mut(t) {
                en.active = true;
                en.appeared = true;
                en.at_road_end = false;
                en.end_of_road = false;
                en.standstill_since = None;
                en.offroad_since = None;
            }
        }
        self.teleport(slot, e, pos);
        self.align_chain(e);
        // The trailers are placed too: their tow vehicle does not pull them this step.
        for t in self.tow_chain(e) {
            if let Some(en) = self.entities.get_mut(t) {
                en.moved_by_action = true;
            }
        }
    }

    pub(super) fn delete_entity(&mut self, slot: usize, name: &str) {
        let Some(e) = self.entity_index(name) else {
            self.warn_action(slot, format!("DeleteEntityAction: unknown entity `{name}`; skipped"));
            return;
        };
        if !self.entities[e].active {
            self.warn_action(slot, format!("DeleteEntityAction: entity `{name}` does not exist (already deleted); skipped"));
            return;
        }
        for t in self.tow_chain(e) {
            if let Some(en) = self.entities.get_mut(t) {
                en.active = false;
                en.appeared = false;
            }
            self.end_actions_of(t);
        }
    }

    /// `e` and the trailers it tows, front to back.
    fn tow_chain(&self, e: usize) -> Vec<usize> {
        let mut chain = vec![e];
        let mut tow = e;
        for _ in 0..MAX_CHAIN {
            match self.trailers.links.get(tow).copied().flatten() {
                Some(t) if !chain.contains(&t) => {
                    chain.push(t);
                    tow = t;
                }
                _ => break,
            }
        }
        chain
    }

    /// End the running action instances of entity `e`; an action none of whose instances is
    /// left running ends.
    fn end_actions_of(&mut self, e: usize) {
        let mut to_end = Vec::new();
        for slot in &mut self.actions {
            if !slot.running || !slot.instances.iter().any(|i| i.entity == Some(e)) {
                continue;
            }
            for inst in &mut slot.instances {
                if inst.entity == Some(e) {
                    inst.rt = super::ActionRt::Done;
                }
            }
            if slot.instances.iter().all(|i| matches!(i.rt, super::ActionRt::Done)) {
                to_end.push(slot.node);
            }
        }
        for n in to_end {
            self.end_element(n);
        }
    }
}

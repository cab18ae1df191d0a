//! AddEntityAction and DeleteEntityAction, as esmini runs them. An entity exists from the
//! start only if the Init has a Private element for it (esmini's ScenarioReader::parseInit
//! activates those, with the trailers they tow; every other entity waits in the pool until an
//! AddEntityAction). Deleting an entity takes it out of the simulation (no trace rows, no
//! default controller, no driver model; entity conditions skip it) together with its trailers,
//! but not out of the storyboard: its actions go on acting on it while it is away, and it comes
//! back as they left it, at the action's position (trailers straight behind it). Adding an
//! entity that exists, or deleting one that does not, is refused as esmini refuses it: the
//! action never starts (its event runs on until stopped), with a warning.

use crate::sim::Sim;
use openscenario::{ActionKind, GlobalAction, Position};

/// Longest tow chain followed (hostile input).
const MAX_CHAIN: usize = 100;

impl<'a> Sim<'a> {
    /// Who exists at the start: the entities the Init has a Private element for, and the
    /// trailers they tow (ScenarioReader::parseInit calls Entities::activateObject for each
    /// Private; Entities::addObject left every declared entity inactive).
    pub(crate) fn initial_presence(&mut self) {
        let named: Vec<usize> = self.scenario.storyboard.init.private.iter().filter_map(|p| self.entity_index(&p.entity)).collect();
        let mut active = vec![false; self.entities.len()];
        for e in named {
            for t in self.tow_chain(e) {
                if let Some(a) = active.get_mut(t) {
                    *a = true;
                }
            }
        }
        for (en, a) in self.entities.iter_mut().zip(active) {
            en.active = a;
            // Entities::addObject marks every new object teleported ("virgin location"); only
            // the active ones have their marks cleared, so one added later still has it.
            en.teleported |= !a;
        }
    }

    /// An AddEntityAction on an entity that exists, or a DeleteEntityAction on one that does
    /// not (or an unknown entity): esmini's AddEntityAction::Start / DeleteEntityAction::Start
    /// return before OSCAction::Start, so the action stays in its init state.
    pub(crate) fn entity_action_refused(&mut self, slot: usize) -> bool {
        let model = self.actions[slot].model;
        let (name, adding) = match &model.kind {
            ActionKind::Global(GlobalAction::AddEntity { entity, .. }) => (entity, true),
            ActionKind::Global(GlobalAction::DeleteEntity { entity }) => (entity, false),
            _ => return false,
        };
        let element = if adding { "AddEntityAction" } else { "DeleteEntityAction" };
        let msg = match self.entity_index(name) {
            None => format!("{element}: unknown entity `{name}`; the action does not start"),
            Some(e) if self.entities[e].active == adding => {
                let state = if adding { "already exists" } else { "does not exist (already deleted)" };
                format!("{element}: entity `{name}` {state}; the action does not start, as in esmini")
            }
            Some(_) => return false,
        };
        self.warn_action(slot, msg);
        true
    }

    pub(super) fn add_entity(&mut self, slot: usize, name: &str, pos: &Position) {
        let Some(e) = self.entity_index(name) else { return };
        for t in self.tow_chain(e) {
            if let Some(en) = self.entities.get_mut(t) {
                en.active = true;
                en.appeared = true;
                // The end-of-road status and flag stay as the entity left them (TeleportTo
                // copies the location only): one that stood stuck at a road's end is stopped
                // again where it is added (motion.rs), until a move clears them.
                en.standstill_since = None;
                en.offroad_since = None;
            }
        }
        // AddEntityAction::Start moves the entity's position itself (no TeleportAction): no
        // "moved" mark, so the default controller drives it on in this very step, unless an
        // action moved it while it was away (the mark stayed: run.rs). Nor a "teleported"
        // mark: the one it has is what it kept while away (motion.rs measures the jump unless
        // it has one). Unlike a TeleportAction it places the entity also while a controller in
        // override mode drives it.
        let (held, jumped) = self.entities.get(e).map_or((false, false), |en| (en.moved_by_action, en.teleported));
        self.put_at(slot, e, pos, "AddEntityAction");
        if let Some(en) = self.entities.get_mut(e) {
            en.moved_by_action = held;
            en.teleported = jumped;
        }
        self.align_chain(e);
    }

    pub(super) fn delete_entity(&mut self, _slot: usize, name: &str) {
        let Some(e) = self.entity_index(name) else { return };
        for t in self.tow_chain(e) {
            if let Some(en) = self.entities.get_mut(t) {
                en.active = false;
                en.appeared = false;
            }
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
}

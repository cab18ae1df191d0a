//! OverrideControllerValueAction as esmini 3.6.0 runs it headless (`OverrideControlAction` in
//! OSCPrivateAction.cpp): the values are stored on the entity and move nothing — esmini's own
//! controllers never read them; only its library hands them to an outside driver — but the
//! action holds control domains (`state.rs`), so starting it ends the entity's running actions
//! on them, and releasing an active override of an entity that has a ghost restarts the ghost
//! (`ScenarioEngine::InjectGhostRestart`, `ghost_restart.rs`). It ends in the step it starts.

pub(crate) mod state;

use self::state::kind_index;
use crate::actions::state::ActionRt;
use crate::sim::Sim;
use crate::Diagnostic;
use openscenario::OverrideValue;

impl<'a> Sim<'a> {
    /// `OverrideControlAction::Start` on entity `e`, value by value in document order.
    pub(crate) fn start_override(&mut self, slot: usize, e: usize, values: &[OverrideValue]) -> ActionRt {
        let has_ghost = self.ghost.as_ref().is_some_and(|g| g.owner == e);
        for v in values {
            let Some(k) = kind_index(&v.kind) else { continue };
            let Some(en) = self.entities.get_mut(e) else { break };
            let released = en.overrides_active[k] && !v.active;
            en.overrides_active[k] = v.active;
            // One restart per released value, as esmini injects them (a second one in the same
            // step sends the ghost to the same place again).
            if has_ghost && released {
                let note = self.override_restart_note(slot, e, &v.kind);
                let Some(ev) = self.nodes[self.actions[slot].node].parent else { continue };
                self.inject_ghost_restart(ev, note);
            }
        }
        self.warn_action(
            slot,
            "OverrideControllerValueAction: the values are recorded and move nothing, as in esmini, whose controllers do not read them (it ends the entity's running actions on the domains it holds)".into(),
        );
        ActionRt::Done
    }

    fn override_restart_note(&self, slot: usize, e: usize, kind: &str) -> Diagnostic {
        let name = self.entities.get(e).map_or("", |en| en.name.as_str());
        let action = &self.nodes[self.actions[slot].node].name;
        let msg = format!(
            "action `{action}` releases the active {kind} override of `{name}`, where esmini restarts its ghost from it: time rewinds by the head start and the rewound steps are logged again (the trace CSV repeats those times, as esmini's log does; the CommonRoad conversion keeps the first pass)"
        );
        Diagnostic::at(&self.actions[slot].model.origin, msg)
    }
}

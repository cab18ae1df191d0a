//! TrafficSignalStateAction and TrafficSignalControllerAction: both take effect when the action
//! starts (so later triggers of the same evaluation already see the new state) and complete at
//! once. The states themselves live in `signals.rs`.

use crate::sim::Sim;

impl<'a> Sim<'a> {
    /// Set signal `name` to `state` now.
    pub(super) fn set_signal_state(&mut self, slot: usize, name: &str, state: &str) {
        if !self.signals.is_known(name) {
            self.warn_action(slot, format!("TrafficSignalStateAction: `{name}` is not a signal id of the road network; its state is kept anyway"));
        }
        self.signals.set_state(self.time, name, state);
    }

    /// Restart controller `controller` in phase `phase` now.
    pub(super) fn set_signal_phase(&mut self, slot: usize, controller: &str, phase: &str) {
        if let Err(msg) = self.signals.set_phase(self.time, controller, phase) {
            self.warn_action(slot, format!("TrafficSignalControllerAction: {msg}; nothing changes"));
        }
    }
}

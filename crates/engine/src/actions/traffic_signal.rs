//! TrafficSignalStateAction takes effect when the action starts (so later triggers of the same
//! evaluation already see the new state) and completes at once. The states themselves live in
//! `signals.rs`. TrafficSignalControllerAction changes nothing (actions/global.rs):
//! esmini 3.6.0 drops it (`ScenarioReader::parseOSCGlobalAction`: "not supported yet") and
//! runs no controller.

use crate::sim::Sim;

impl<'a> Sim<'a> {
    /// Set signal `name` to `state` now.
    pub(super) fn set_signal_state(&mut self, slot: usize, name: &str, state: &str) {
        if !self.signals.is_known(name) {
            self.warn_action(slot, format!("TrafficSignalStateAction: `{name}` is not a signal id of the road network; its state is kept anyway"));
        }
        self.signals.set_state(self.time, name, state);
    }
}

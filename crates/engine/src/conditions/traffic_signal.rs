//! TrafficSignalCondition (true while the signal is in the state) and
//! TrafficSignalControllerCondition (true while the controller is in the phase), read from
//! `signals.rs`. A signal nobody has set has no state: the condition is false.

use super::ConditionRt;
use crate::sim::Sim;

impl<'a> Sim<'a> {
    pub(super) fn check_signal(&mut self, c: &mut ConditionRt<'a>, name: &str, state: &str) -> bool {
        if !self.signals.is_known(name) && !c.warned {
            c.warned = true;
            let msg = format!("condition `{}`: `{name}` is not a signal id of the road network", c.model.name);
            self.warnings.push(crate::Diagnostic::at(&c.model.origin, msg));
        }
        self.signals.is_in(name, state)
    }

    pub(super) fn check_signal_controller(&mut self, c: &mut ConditionRt<'a>, controller: &str, phase: &str) -> bool {
        match self.signals.controller(controller) {
            Some(i) => self.signals.controllers[i].phase_name() == Some(phase),
            None => self.warn_once(c, format!("traffic signal controller `{controller}` is not defined in the RoadNetwork")),
        }
    }
}

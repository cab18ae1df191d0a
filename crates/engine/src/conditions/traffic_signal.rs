//! TrafficSignalCondition (true while the signal is in the state), read from `signals.rs`. A
//! signal nobody has set has no state: the condition is false. (TrafficSignalControllerCondition
//! is left out of its group, as esmini does: `by_value::ignored_by_esmini`.)

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
}

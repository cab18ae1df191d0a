//! Global actions: parameter set (a parameter modify is only a warning, as esmini 3.6.0 reads
//! none), variable set / modify, traffic-signal state and controller
//! phase (`traffic_signal.rs`; the phase is only a warning, as esmini 3.6.0 runs no
//! controller), add / delete entity (`add_delete_entity.rs`), environment (recorded in
//! `Run::environment`); everything else is a warning.

use crate::sim::Sim;
use openscenario::GlobalAction;

impl<'a> Sim<'a> {
    pub(super) fn run_global(&mut self, slot: usize, g: &GlobalAction) {
        match g {
            GlobalAction::ParameterSet { parameter, value } => {
                if !self.params.set(parameter, value) {
                    self.warn_action(slot, format!("ParameterSetAction: parameter `{parameter}` was not declared"));
                }
            }
            // esmini 3.6.0 reads only a ParameterAction's SetAction ("ParameterAction
            // ModifyAction not supported yet", ScenarioReader::parseOSCGlobalAction): the event
            // runs without it and the parameter keeps its value.
            GlobalAction::ParameterModify { parameter, .. } => self.warn_action(
                slot,
                format!("ParameterModifyAction on `{parameter}` is not supported by esmini 3.6.0; the parameter keeps its value"),
            ),
            GlobalAction::VariableSet { variable, value } => {
                if !self.vars.set(variable, value) {
                    self.warn_action(slot, format!("VariableSetAction: variable `{variable}` was not declared"));
                }
            }
            GlobalAction::VariableModify { variable, rule } => {
                match self.vars.modify(variable, rule) {
                    crate::values::Modified::Done => {}
                    crate::values::Modified::Missing => {
                        self.warn_action(slot, format!("VariableModifyAction: variable `{variable}` is missing or not a number"))
                    }
                    // VariableAddAction / VariableMultiplyByAction act on integers and doubles only
                    crate::values::Modified::NotNumeric => self.warn_action(
                        slot,
                        format!("VariableModifyAction: variable `{variable}` is a string or boolean; it keeps its value, as in esmini"),
                    ),
                }
            }
            GlobalAction::Environment(env) => {
                let time = self.time;
                self.environment.push(crate::recorded::EnvironmentChange { time, environment: env.clone() });
            }
            GlobalAction::AddEntity { entity, position } => self.add_entity(slot, entity, position),
            GlobalAction::DeleteEntity { entity } => self.delete_entity(slot, entity),
            GlobalAction::TrafficSignalState { name, state } => self.set_signal_state(slot, name, state),
            // esmini 3.6.0 drops it (ScenarioReader::parseOSCGlobalAction) and runs no controller
            GlobalAction::TrafficSignalController { controller, phase } => self.warn_action(
                slot,
                format!("TrafficSignalControllerAction (controller `{controller}`, phase `{phase}`) is not supported by esmini 3.6.0, which runs no signal controller; nothing changes"),
            ),
            other => self.warn_action(slot, format!("{} is not supported yet; the action completes at once", other.element_name())),
        }
    }
}

//! Global actions: parameter and variable set / modify; everything else is a warning (part 2
//! adds entities, traffic signals and the environment).

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
            GlobalAction::ParameterModify { parameter, rule } => {
                if !self.params.modify(parameter, rule) {
                    self.warn_action(slot, format!("ParameterModifyAction: parameter `{parameter}` is missing or not a number"));
                }
            }
            GlobalAction::VariableSet { variable, value } => {
                if !self.vars.set(variable, value) {
                    self.warn_action(slot, format!("VariableSetAction: variable `{variable}` was not declared"));
                }
            }
            GlobalAction::VariableModify { variable, rule } => {
                if !self.vars.modify(variable, rule) {
                    self.warn_action(slot, format!("VariableModifyAction: variable `{variable}` is missing or not a number"));
                }
            }
            GlobalAction::Environment(_) => {}
            other => self.warn_action(slot, format!("{} is not supported yet; the action completes at once", other.element_name())),
        }
    }
}

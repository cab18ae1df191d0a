//! Value conditions: simulation time, parameters, variables, storyboard element states.

use super::ConditionRt;
use crate::rules::compare;
use crate::sim::Sim;
use crate::storyboard::{State, Transition};
use openscenario::{StoryboardElementState as Want, ValueCondition};

impl<'a> Sim<'a> {
    pub(super) fn check_value(&mut self, c: &mut ConditionRt<'a>, v: &ValueCondition) -> bool {
        match v {
            ValueCondition::SimulationTime { value, rule } => compare(self.time, *value - c.time_shift, *rule),
            ValueCondition::Parameter { parameter, value, rule } => match self.params.compare(parameter, value, *rule) {
                Some(result) => result,
                None => self.warn_once(c, format!("parameter `{parameter}` is not declared")),
            },
            ValueCondition::Variable { variable, value, rule } => match self.vars.compare(variable, value, *rule) {
                Some(result) => result,
                None => self.warn_once(c, format!("variable `{variable}` is not declared")),
            },
            ValueCondition::StoryboardElementState { state, element, .. } => {
                let Some(target) = c.element else {
                    return self.warn_once(c, format!("storyboard element `{element}` not found"));
                };
                // Changes since the last evaluation count once; otherwise the latest state holds
                // (a transition is only true in the evaluation that sees it).
                let mut result = false;
                let mut seen = None;
                for &(node, st, tr) in self.state_log.get(c.cursor..).unwrap_or(&[]) {
                    if node == target {
                        result |= state_matches(*state, st, Some(tr));
                        seen = Some((st, tr));
                    }
                }
                c.cursor = self.state_log.len();
                match seen {
                    Some(s) => c.latest = Some(s),
                    None => result = c.latest.is_some_and(|(st, _)| state_matches(*state, st, None)),
                }
                result
            }
            ValueCondition::TrafficSignal { name, state } => self.check_signal(c, name, state),
            // Never evaluated: `TriggerRt::new` leaves these out of their group (see `ignored_by_esmini`).
            ValueCondition::TrafficSignalController { .. } | ValueCondition::TimeOfDay { .. } | ValueCondition::UserDefinedValue { .. } => false,
        }
    }

    /// Warn once per condition and evaluate to false.
    pub(super) fn warn_once(&mut self, c: &mut ConditionRt<'a>, msg: String) -> bool {
        if !c.warned {
            c.warned = true;
            self.warnings.push(crate::Diagnostic::at(&c.model.origin, format!("condition `{}`: {msg}", c.model.name)));
        }
        false
    }
}

/// Why esmini 3.6.0 reads past a value condition, if it does: ScenarioReader::parseOSCCondition
/// logs "not supported yet. Ignoring." for every ByValueCondition other than SimulationTime,
/// Parameter, Variable, StoryboardElementState and TrafficSignal, and returns no condition, so
/// ScenarioReader::parseTrigger leaves it out of its group. The group is the AND of the rest; a
/// group left with nothing is false (ConditionGroup::Evaluate).
pub(crate) fn ignored_by_esmini(v: &ValueCondition) -> Option<&'static str> {
    match v {
        ValueCondition::TrafficSignalController { .. } | ValueCondition::TimeOfDay { .. } | ValueCondition::UserDefinedValue { .. } => {
            Some("not supported there: \"not supported yet. Ignoring.\"")
        }
        _ => None,
    }
}

fn state_matches(want: Want, st: State, tr: Option<Transition>) -> bool {
    match want {
        Want::StandbyState => st == State::Standby,
        Want::RunningState => st == State::Running,
        Want::CompleteState => st == State::Complete,
        Want::StartTransition => tr == Some(Transition::Start),
        Want::EndTransition => tr == Some(Transition::End),
        Want::StopTransition => tr == Some(Transition::Stop),
        Want::SkipTransition => tr == Some(Transition::Skip),
    }
}

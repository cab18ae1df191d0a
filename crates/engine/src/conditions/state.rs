//! What the triggers hold while a run goes on: each condition's last values, edge memory,
//! delay history and the entities that made it true. Data only: the modules of `conditions/`
//! change it.

use crate::storyboard::{State, Transition};
use openscenario::Condition;

/// One condition with its evaluation memory.
#[derive(Debug, Clone)]
pub(crate) struct ConditionRt<'a> {
    pub model: &'a Condition,
    pub(super) last_result: bool,
    /// Evaluated since the trigger last fired (edges need a previous value).
    pub(super) evaluated: bool,
    pub(super) value: bool,
    /// (time, edge-filtered value) at each change, for delays.
    pub(super) history: Vec<(f64, bool)>,
    pub triggering: Vec<usize>,
    /// Seconds a SimulationTime condition fires early (a ghost's head start, `ghost/`).
    pub time_shift: f64,
    /// The triggering entities for which the condition held when it was last true (read by
    /// `selectTriggeringEntities`), and the scratch list of the evaluation in progress.
    pub fired_by: Vec<usize>,
    pub(super) hits: Vec<usize>,
    pub other: Option<usize>,
    pub element: Option<usize>,
    pub cursor: usize,
    pub latest: Option<(State, Transition)>,
    pub warned: bool,
}

#[derive(Debug, Clone, Default)]
pub(crate) struct TriggerRt<'a> {
    pub groups: Vec<Vec<ConditionRt<'a>>>,
}

//! The storyboard tree flattened into a vector of nodes (parents before children, in document
//! order), each with its state, triggers and execution counts.

use openscenario::Priority;

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Kind {
    Storyboard,
    Story,
    Act,
    ManeuverGroup,
    Maneuver,
    Event,
    Action,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum State {
    Init,
    Standby,
    Running,
    Complete,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Transition {
    InitToStandby,
    Start,
    End,
    Stop,
    Skip,
}

impl State {
    pub(crate) fn name(self) -> &'static str {
        match self {
            State::Init => "init",
            State::Standby => "standby",
            State::Running => "running",
            State::Complete => "complete",
        }
    }
}

impl Transition {
    pub(crate) fn name(self) -> &'static str {
        match self {
            Transition::InitToStandby => "initToStandby",
            Transition::Start => "start",
            Transition::End => "end",
            Transition::Stop => "stop",
            Transition::Skip => "skip",
        }
    }
}

/// One storyboard element.
#[derive(Debug, Clone)]
pub(crate) struct Node {
    pub kind: Kind,
    pub name: String,
    pub parent: Option<usize>,
    pub children: Vec<usize>,
    pub state: State,
    /// Index into the run's triggers; `None`: no trigger (a start then happens at once).
    pub start_trigger: Option<usize>,
    pub stop_trigger: Option<usize>,
    /// `maximumExecutionCount` of maneuver groups and events (others: 1).
    pub max_executions: u32,
    /// Signed: esmini's `ResetEvents` can drive it below zero (`ghost/restart.rs`).
    pub executions: i64,
    pub priority: Priority,
    /// Index into the run's action slots (action nodes only).
    pub action: Option<usize>,
}

impl Node {
    pub(crate) fn new(kind: Kind, name: &str, parent: Option<usize>) -> Node {
        Node {
            kind,
            name: name.to_string(),
            parent,
            children: Vec::new(),
            state: State::Init,
            start_trigger: None,
            stop_trigger: None,
            max_executions: 1,
            executions: 0,
            priority: Priority::Override,
            action: None,
        }
    }
}

/// A maneuver group whose actors are chosen when it starts.
#[derive(Debug, Clone)]
pub(crate) struct TriggeringActors {
    /// The maneuver group's node.
    pub group: usize,
    /// The actors its Actors element lists.
    pub listed: Vec<usize>,
    /// Its private action slots.
    pub slots: Vec<usize>,
}

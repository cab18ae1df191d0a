//! What a ghost is during a run: the entity it runs ahead of, its head start, its trail and
//! esmini's ghost mode and clock. Data only: `ghost/mod.rs`, `trail.rs` and
//! `restart.rs` change it.

use crate::ghost::trail::Trail;

#[derive(Debug, Clone)]
pub(crate) struct Ghost {
    /// The ghost entity.
    pub entity: usize,
    /// The entity it runs ahead of (the only one that follows it).
    pub owner: usize,
    pub headstart: f64,
    pub trail: Trail,
    /// esmini's simulation time, accumulated step by step.
    pub clock: f64,
    /// The latest `clock` reached (esmini's `trueTime_`): a rewound run catches up to it.
    pub true_clock: f64,
    /// esmini's ghost mode (`SE_Env::GetGhostMode`).
    pub mode: GhostMode,
    /// Events that teleport the ghost back to its entity when they start (esmini's
    /// `AddedGhostTeleport`), each with the condition that made it one.
    pub restart_events: Vec<(usize, crate::Diagnostic)>,
    /// While the actions of an event start after its added teleport: how much earlier they
    /// start (esmini's `Event::Start` passes them the time less the head start).
    pub start_shift: f64,
    /// The ghost was restarted in the last step and its motion then not measured (esmini's
    /// `ScenarioEngine::prepareStep` skips the ghost in RESTART mode): its state before that
    /// step stays the one to measure the next step's move from.
    pub unmeasured: bool,
}

/// esmini's ghost modes: `Restart` for the rest of the step in which the ghost was sent back to
/// its entity, then `Restarting` while the rewound time catches up (the head start before time
/// 0 is run the same way), else `Normal`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum GhostMode {
    Normal,
    Restart,
    Restarting,
}

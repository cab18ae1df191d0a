//! What a running SynchronizeAction remembers: the master, both targets, the final speed and
//! the phase of esmini's speed profile.

use crate::positions::Placement;

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Mode {
    None,
    NonLinear,
    Linear,
    Stopped,
    StopImmediately,
    Waiting,
    SteadyState,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Submode {
    None,
    Concave,
    Convex,
}

#[derive(Debug, Clone, Copy)]
pub(super) enum Final {
    Absolute(f64),
    Relative { value: f64, factor: bool },
}

#[derive(Debug, Clone)]
pub(crate) struct SynchronizeRt {
    pub(super) master: usize,
    pub(super) target_master: Placement,
    pub(super) target: Placement,
    pub(super) final_speed: Option<Final>,
    pub(super) steady_dist: Option<f64>,
    pub(super) steady_time: Option<f64>,
    pub(super) tolerance: f64,
    pub(super) tolerance_master: f64,
    pub(super) mode: Mode,
    pub(super) submode: Submode,
    pub(super) last_dist: f64,
    pub(super) last_master_dist: f64,
}

impl SynchronizeRt {
    /// What esmini's action object keeps for its event's next execution.
    pub(crate) fn kept(&self) -> SynchronizeKept {
        SynchronizeKept {
            mode: self.mode,
            submode: self.submode,
            last_dist: self.last_dist,
            last_master_dist: self.last_master_dist,
            steady_dist: self.steady_dist,
        }
    }
}

/// What esmini's SynchronizeAction object carries from one execution of its event to the next:
/// Start resets none of its speed profile's mode and submode nor the last distances (so an
/// execution that starts no nearer its target than the last one ended is done at once, "missed
/// destination"), and a steady-state time stays the distance the first Start made of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SynchronizeKept {
    pub(super) mode: Mode,
    pub(super) submode: Submode,
    pub(super) last_dist: f64,
    pub(super) last_master_dist: f64,
    pub(super) steady_dist: Option<f64>,
}

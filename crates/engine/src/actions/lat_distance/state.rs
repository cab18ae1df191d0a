//! What a running LateralDistanceAction remembers.

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Phase {
    Init,
    Rigid,
    Dynamic,
}

#[derive(Debug, Clone)]
pub(crate) struct LatDistanceRt {
    /// The action's slot, for its warning.
    pub(super) slot: usize,
    pub(super) target: usize,
    /// Signed wanted t of the actor relative to the reference (+ left).
    pub(super) wanted: f64,
    pub(super) continuous: bool,
    pub(super) max_acc: f64,
    pub(super) max_acc_rate: f64,
    pub(super) max_speed: f64,
    pub(super) phase: Phase,
    pub(super) lat_vel: f64,
    pub(super) acceleration: f64,
    pub(super) old: (f64, f64),
}

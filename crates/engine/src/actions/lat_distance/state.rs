//! What a running LateralDistanceAction remembers.

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Phase {
    Init,
    Rigid,
    Dynamic,
}

/// The coordinate system the distance is kept in, as esmini acts on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Frame {
    /// t along the road (`CS_ROAD`).
    Road,
    /// The reference's own axes (`CS_ENTITY`).
    Entity,
    /// Any other (lane, trajectory, world): esmini's step does nothing and never ends.
    Idle,
}

#[derive(Debug, Clone)]
pub(crate) struct LatDistanceRt {
    /// The action's slot, for its warning.
    pub(super) slot: usize,
    pub(super) target: usize,
    pub(super) frame: Frame,
    /// Signed wanted t of the actor relative to the reference (+ left).
    pub(super) wanted: f64,
    pub(super) continuous: bool,
    pub(super) max_acc: f64,
    pub(super) max_acc_rate: f64,
    pub(super) max_speed: f64,
    /// Whether the constraints leave the road-frame motion unlimited (esmini's MOVE_RIGID).
    pub(super) rigid: bool,
    pub(super) phase: Phase,
    pub(super) lat_vel: f64,
    pub(super) acceleration: f64,
    pub(super) old: (f64, f64),
    /// esmini's `distance_` and `sign_` as this execution's Start left them (in esmini's own
    /// signs: the road frame's distance is negative to the left), for the next execution.
    pub(super) esmini_distance: f64,
    pub(super) esmini_sign: f64,
}

impl LatDistanceRt {
    /// What esmini's action object keeps for its event's next execution.
    pub(crate) fn kept(&self) -> LatDistanceKept {
        LatDistanceKept { distance: self.esmini_distance, sign: self.esmini_sign, lat_vel: self.lat_vel, acceleration: self.acceleration }
    }
}

/// What esmini's LatDistanceAction object carries from one execution of its event to the next:
/// the object is built once per actor and only started again, and neither Start nor the first
/// step resets its distance (Start adds the freespace half-widths to it again), its spring's
/// lateral speed or its acceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LatDistanceKept {
    pub(super) distance: f64,
    pub(super) sign: f64,
    pub(super) lat_vel: f64,
    pub(super) acceleration: f64,
}

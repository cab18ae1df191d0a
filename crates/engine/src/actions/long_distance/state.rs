//! What a running LongitudinalDistanceAction remembers.

use openscenario::CoordinateSystem;

#[derive(Debug, Clone)]
pub(crate) struct LongDistanceRt {
    pub(super) target: usize,
    /// Distance in m, or time gap in s when `time_gap`.
    pub(super) value: f64,
    pub(super) time_gap: bool,
    pub(super) freespace: bool,
    pub(super) continuous: bool,
    pub(super) cs: CoordinateSystem,
    /// +1 trailing (reference ahead), -1 leading; `None`: the value's own sign (OpenSCENARIO
    /// 1.0, which has no displacement).
    pub(super) side: Option<f64>,
    pub(super) max_acc: f64,
    pub(super) max_dec: f64,
    pub(super) max_acc_rate: f64,
    pub(super) max_dec_rate: f64,
    pub(super) max_speed: f64,
    pub(super) acceleration: f64,
}

impl LongDistanceRt {
    /// What esmini's action object keeps for its event's next execution.
    pub(crate) fn kept(&self) -> LongDistanceKept {
        LongDistanceKept { side: self.side, acceleration: self.acceleration }
    }
}

/// What esmini's LongDistanceAction object carries from one execution of its event to the next:
/// an "any" displacement as the first Start resolved it (Start resolves only "any", and leaves
/// the side it chose in the object), and the acceleration its jerk limit starts from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LongDistanceKept {
    pub(super) side: Option<f64>,
    pub(super) acceleration: f64,
}

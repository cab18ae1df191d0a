//! What a running LaneChangeAction remembers: its transition and where the entity is in the
//! target lane.

use crate::dynamics::Transition;
use crate::roads::LanePos;

#[derive(Debug, Clone)]
pub(crate) struct LaneChangeRt {
    pub transition: Transition,
    /// The entity's position expressed in the target lane.
    pub internal: LanePos,
    /// The sign of a missing target lane's id, applied to the offset in the first step only:
    /// esmini's failed Position::SetLanePos keeps that offset in the entity's own lane
    /// (LatLaneChangeAction::Step); `None` when the target lane exists.
    pub missing_lane_sign: Option<f64>,
}

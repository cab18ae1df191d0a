//! What a running LaneChangeAction remembers: its transition and where the entity is in the
//! target lane.

use crate::dynamics::Transition;
use crate::roads::LanePos;

#[derive(Debug, Clone)]
pub(crate) struct LaneChangeRt {
    pub transition: Transition,
    /// The entity's position expressed in the target lane.
    pub internal: LanePos,
}

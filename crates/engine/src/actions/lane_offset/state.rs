//! What a running LaneOffsetAction remembers.

use crate::dynamics::Transition;

#[derive(Debug, Clone)]
pub(crate) struct LaneOffsetRt {
    pub transition: Transition,
}

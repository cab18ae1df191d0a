//! What a running LaneOffsetAction remembers.

use crate::dynamics::Transition;

#[derive(Debug, Clone)]
pub struct LaneOffsetRt {
    pub transition: Transition,
}

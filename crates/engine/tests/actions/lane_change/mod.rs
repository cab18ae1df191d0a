//! LaneChangeAction: its transition, a step of it, a target lane the road does not have.

mod missing_lane;
mod step;
mod transition;

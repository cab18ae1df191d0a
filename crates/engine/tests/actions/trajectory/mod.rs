//! FollowTrajectoryAction, forwards and backwards.

mod follow;
mod reverse;

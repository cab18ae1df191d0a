//! FollowTrajectoryAction, forwards and backwards.

mod follow;
mod nurbs_headings;
mod reverse;
mod timing;

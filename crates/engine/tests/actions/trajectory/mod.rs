//! FollowTrajectoryAction, forwards and backwards.

mod clothoid_start_time;
mod follow;
mod nurbs_headings;
mod reverse;
mod time_out_of_range;
mod timing;

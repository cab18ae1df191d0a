//! SynchronizeAction and its tolerances.

mod basic;
mod master_against_its_lane;
mod master_moving_away;
mod master_standing;
mod on_trajectories;
mod tolerance;
mod world_targets;

//! SpeedAction and SpeedProfileAction: targets, transition shapes, limits.

mod distance_executed_again;
mod profile;
mod profile_limits;
mod relative;
mod step_shape;

//! SpeedAction and SpeedProfileAction: targets, transition shapes, limits.

mod profile;
mod profile_limits;
mod relative;
mod step_shape;

//! AngleCondition: heading, pitch and roll, in every frame.

mod banked_frame;
mod heading;
mod pitch_roll;
mod trajectory_frame;

//! What a controller in override mode (ACC) does to the storyboard's actions on its entity.

mod override_speed_action;
mod override_teleport;

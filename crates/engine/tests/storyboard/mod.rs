//! Storyboard rules: repeated maneuver groups, triggering entities.

mod global_actions_stop;
mod repeat_resets_triggers;
mod select_triggering;

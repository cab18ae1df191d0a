//! Storyboard rules: repeated maneuver groups, triggering entities.

mod repeat_resets_triggers;
mod select_triggering;

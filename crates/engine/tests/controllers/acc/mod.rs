//! The ACC: what a controller in override mode does to the storyboard's actions on its entity,
//! its first frame and its look-ahead.

mod activate_before_1_3_switches_off;
mod activate_by_controller_ref;
mod assigned_beside_looming;
mod assigned_controller_unnamed_before_1_3;
mod controller_named_by_its_object_controller;
mod first_frame;
mod lane_change_off_driving_lanes;
mod lane_change_on_route;
mod lane_change_onto_opposite_road;
mod lead_after_section_walk;
mod lead_behind_wrapped_driving_direction;
mod lead_driven_past_road_end;
mod lead_stopped_at_road_end;
mod leads_across_junctions;
mod lookahead_same_road;
mod override_add_entity;
mod override_distance_actions;
mod override_moves;
mod override_off_road;
mod override_route;
mod override_speed_action;
mod override_speed_profile;
mod override_teleport;
mod override_timed_trajectory;
mod road_end_moving_sideways;
mod road_end_then_trajectory;
mod timed_clothoid_start_speed;

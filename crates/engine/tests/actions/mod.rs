//! Each action, checked against hand computations or esmini 3.6.0's runs.

mod add_delete_entity;
mod assign_controller_never_ends;
mod basic;
mod executed_again;
mod lane_change;
mod lane_offset_relative;
mod lateral_distance;
mod longitudinal_distance_across_junction_turn;
mod longitudinal_distance_against_lane;
mod longitudinal_distance_and_acc;
mod longitudinal_distance_any_side;
mod longitudinal_distance_freespace;
mod longitudinal_distance_in_1_0;
mod longitudinal_distance_junction_arm;
mod longitudinal_distance_limits;
mod override_controller_value;
mod parameter_modify_ignored;
mod recorded;
mod route_world_waypoints;
mod routes;
mod speed;
mod speed_from_displacement;
mod synchronize;
mod teleport;
mod trailers;
mod trajectory;

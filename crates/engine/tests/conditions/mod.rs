//! Triggers and each condition, checked against hand computations or esmini 3.6.0's runs.

mod acceleration_curve;
mod angle;
mod basic;
mod clearance_across_roads;
mod clearance_corners_across_road_end;
mod clearance_free_space_corners;
mod clearance_offroad_headway;
mod directed_speed;
mod distance_unlinked_roads;
mod duration_held_for_next_entity;
mod end_of_road_acc;
mod freespace_across_roads;
mod freespace_distance_sign;
mod freespace_point_corners;
mod freespace_towing_chains;
mod ignored_value_conditions;
mod lateral_road_distance_sign;
mod offroad_lane_offset;
mod reach_position_all;
mod rule_tolerance;
mod standstill_clock;
mod ttc_point_on_overlapping_roads;
mod ttc_relative_position;
mod typed_values;
mod undefined_headway_ttc;
mod vertical_motion;

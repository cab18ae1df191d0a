//! Moving along the road: banking, raised lanes, lanes that end, junction choice.

mod centre_of_curvature;
mod eight_links_per_move;
mod end_of_road_speed;
mod ending_lane;
mod junction_connection_entering_at_end;
mod junction_lane_link_to_missing_lane;
mod junction_random;
mod lane_index_past_section;
mod lane_offset_s_after_trajectory_jump;
mod lane_section_into_a_stop_lane;
mod looming_lane_lock_on_steep_bank;
mod raised_lanes;
mod reversing_through_junctions;
mod road_link_without_lane_links;
mod route_into_counter_connection;
mod sloped_banked;
mod straight_heading_either_side_of_zero;
mod superelevation;
mod unlinked_lane_keeps_heading;

//! Positions given in road and lane terms, as esmini resolves them.

mod heading_across_road;
mod lane_drift_headings;
mod orientation_untyped;
mod relative_across_junctions;
mod relative_junction_tie;
mod relative_lane_ds;
mod relative_lane_missing_lane;
mod relative_object_on_a_banked_road;
mod relative_position_on_a_banked_road;
mod road_id_leading_number;
mod road_position_against_lane;
mod road_position_heading;
mod route_position_against_lane;
mod route_position_dropped_waypoints;
mod route_position_from_current_entity;
mod route_position_lane_free_last_hop;
mod route_position_missing_lane_waypoint;
mod route_position_on_missing_lane;
mod route_position_past_route_end;
mod trajectory_position_polyline_headings;
mod world_point_beside_a_road_end;
mod world_point_off_road;
mod world_point_on_overlapping_roads;
mod world_point_on_road_past_a_bend;
mod world_position_on_a_hill;
mod world_position_under_a_bridge;

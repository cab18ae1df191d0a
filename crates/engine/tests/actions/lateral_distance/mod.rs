//! LateralDistanceAction on one road and across roads, in road and entity coordinates.

mod across_junction;
mod across_roads;
mod domain;
mod entity_frame;
mod entity_frame_dead_end;
mod entity_frame_heading_against_road;
mod jump_across_negative_heading;
mod jump_on_banked_road;
mod jump_point_as_given;
mod lane_path;
mod reference_lane_unlinked;
mod reference_on_road_entered_at_its_start;
mod repeated;
mod rigid_heading;
mod rigid_right_angle;
mod road_coordinates;
mod road_ends;

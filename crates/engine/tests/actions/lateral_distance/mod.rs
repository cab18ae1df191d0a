//! LateralDistanceAction on one road and across roads, in road and entity coordinates.

mod across_junction;
mod across_roads;
mod domain;
mod entity_frame;
mod lane_path;
mod rigid_heading;
mod road_coordinates;
mod road_ends;

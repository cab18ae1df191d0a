//! The road network as the engine sees it: lane geometry without allocation, a position
//! attached to a lane, and moving along the lanes through sections, roads and junctions.

pub mod banking;
pub mod junction_connections;
pub mod lane_geometry;
pub mod lane_kind;
pub mod lane_position;
pub mod lane_shape;
pub mod lane_slope;
pub mod lane_snap;
pub mod locate;
pub mod offroad;
pub mod pose_memo;
pub mod road_distance;
pub mod road_follow;
pub mod road_path;
pub mod zero_width;

pub use lane_position::LanePos;
pub use road_follow::{move_along_road_s, move_along_route, move_along_route_drawing, move_along_s, MoveStatus};

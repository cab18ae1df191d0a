//! The road network as the engine sees it: lane geometry without allocation, a position
//! attached to a lane, and moving along the lanes through sections, roads and junctions.

pub(crate) mod banking;
pub(crate) mod driving_direction;
pub(crate) mod junction_connections;
pub(crate) mod junction_entry;
pub(crate) mod lane_geometry;
pub(crate) mod lane_height;
pub(crate) mod lane_position;
pub(crate) mod lane_shape;
pub(crate) mod lane_side;
pub(crate) mod lane_slope;
pub(crate) mod lane_snap;
pub(crate) mod locate;
pub(crate) mod offroad;
pub(crate) mod past_end;
pub(crate) mod pose_memo;
pub(crate) mod road_distance;
pub(crate) mod road_follow;
pub(crate) mod road_id;
pub(crate) mod road_path;
pub(crate) mod track_pos;
pub(crate) mod zero_width;

pub(crate) use lane_position::LanePos;
pub(crate) use road_follow::{move_along_road_s, move_along_route_drawing, move_along_s, move_along_s_drawn, MoveStatus};

//! LateralDistanceAction on one road and across roads.

mod across_roads;
mod road_coordinates;

//! Positions given in road and lane terms, as esmini resolves them.

mod relative_lane_ds;
mod road_position_heading;

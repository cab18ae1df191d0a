//! Moving along the road: banking, lanes that end, junction choice.

mod end_of_road_speed;
mod ending_lane;
mod junction_random;
mod reversing_through_junctions;
mod sloped_banked;
mod superelevation;

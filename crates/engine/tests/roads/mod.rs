//! Moving along the road: banking, lanes that end, junction choice.

mod ending_lane;
mod junction_random;
mod superelevation;

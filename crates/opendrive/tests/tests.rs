//! The OpenDRIVE reader's tests, one binary: lane geometry on hand-written maps, road
//! coordinates round trips and loading on every corpus map, malformed, mutated and hostile input.

mod common;

mod corpus_load;
mod hostile_arc;
mod lane_geometry;
mod malformed;
mod mutation;
mod round_trip;

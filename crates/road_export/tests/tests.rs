//! The road_export tests, one binary: modules by feature.

mod common;

mod esmini_load;
mod generated;
mod hostile;
mod joints;
mod lane_sections;
mod layout;
mod map_round_trip;
mod schema;

//! The typed OpenDRIVE model (f64 throughout). Plain data; geometry lives in `geometry`
//! and in the `road_geometry` impls.

pub mod header;
pub mod junction;
pub mod lanes;
pub mod objects;
pub mod poly;
pub mod road;
pub mod signals;

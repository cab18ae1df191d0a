//! `engine`: runs a resolved OpenSCENARIO scenario on an OpenDRIVE road network at a fixed step
//! and returns what happened — every entity's state at every step, the storyboard's state
//! transitions, and warnings for whatever it could not do.
//!
//! It knows the `openscenario` model and the `opendrive` road network, and nothing of CommonRoad.

pub mod trace;

pub use trace::{EntityTrace, RoadPos, Sample, StoryboardEvent, Trace};

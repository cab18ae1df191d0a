//! OpenDRIVE (1.4–1.8) for osc2cr: the parser into a typed f64 model, the plan-view and
//! lane geometry, and road coordinates both ways ((road, lane, s, offset) → world and
//! world → nearest (road, lane, s, t)), plus the road/lane topology helpers the lanelet
//! converter and the engine build on.
//!
//! This crate knows nothing of OpenSCENARIO or CommonRoad. World coordinates are the
//! file's own x/y (the header `<offset>` is kept in [`Header`] but not applied, as esmini
//! does). Errors carry file, line and column; warnings are returned, never printed.

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

pub mod driving_direction;
pub mod error;
pub mod geometry;
pub mod links;
pub mod model;
pub mod network;
pub mod osi_points;
mod parse;
pub mod projection;
pub mod road_geometry;
pub mod spatial_index;
pub mod traffic_light;

pub use diagnostic::{Diagnostic, LineCol};
pub use driving_direction::{drives_along_s, driving_heading};
pub use error::Error;
pub use geometry::{CurvePose, Geometry, PRange, Shape};
pub use links::{section_at_end, LaneRef, RoadEnd};
pub use model::header::{Header, HeaderOffset};
pub use model::junction::{Connection, Control, Controller, Junction, JunctionController, JunctionType, LaneLink};
pub use model::lanes::{Lane, LaneChange, LaneHeight, LaneSection, LaneSpeed, LaneType, RoadMark, RoadMarkType};
pub use model::objects::{Object, ObjectRepeat, RepeatEnds};
pub use model::poly::CubicRecord;
pub use model::road::{ContactPoint, ElementDir, ElementType, Road, RoadKind, RoadLink, RoadTypeRecord, SpeedLimit, TrafficRule};
pub use model::signals::{LaneValidity, Signal, SignalOrientation, SignalReference};
pub use network::{load, parse_str, Loaded, RoadNetwork};
pub use osi_points::{osi_points, road_osi_points};
pub use projection::LanePosition;
pub use road_geometry::{LaneBorders, WorldPose};
pub use traffic_light::traffic_light_lamps;

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

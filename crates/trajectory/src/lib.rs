//! Trajectory shapes of OpenSCENARIO (polyline, clothoid, clothoid spline, NURBS) turned into
//! arc-length-parameterised 2-D paths with optional time stamps, for FollowTrajectoryAction
//! and TrajectoryPosition.
//!
//! This crate owns the geometry of a trajectory and its own time axis. It does not know
//! the road network, entities or the simulation clock: vertex positions are resolved to
//! world poses by a closure the engine passes in, and [`TimeMapping`] only converts between
//! simulation time and trajectory time as the engine asks. Where the standard is silent
//! the behaviour follows esmini (corner blending of polyline headings, NURBS sampling and
//! control-point time interpolation).

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod angle;
mod constructors;
mod error;
mod from_shape;
mod nurbs;
mod nurbs_path;
mod path;
mod polyline;
mod pose;
mod sampled;
mod spiral;
mod time_mapping;
mod time_table;

/// esmini's SMALL_NUMBER (CommonMini.hpp), the tolerance of its trajectory code: vertex
/// filtering, the NURBS parameter clamp and which basis values count.
const ESMINI_SMALL: f64 = 1e-6;

pub use constructors::{filter_vertices, PolylineVertex, SplineSegment, MAX_ITEMS, MAX_LENGTH};
pub use error::Error;
pub use from_shape::{gives_heading, Placer, Resolver};
pub use nurbs::Nurbs;
pub use path::Path;
pub use polyline::Interpolation;
pub use pose::{PathPoint, Pose};
pub use time_mapping::{TimeDomain, TimeMapping};
pub use time_table::TimeTable;

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

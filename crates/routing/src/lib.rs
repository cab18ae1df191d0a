//! Route planning over an OpenDRIVE road network for AssignRouteAction, AcquirePositionAction
//! and RoutePosition: from waypoints given as (road, lane, s) to the sequence of lanes an
//! entity drives through, respecting driving directions, lane links through lane sections
//! and junctions, and lane changes between adjacent same-direction lanes (at a cost).
//!
//! This crate knows the road network (crate `opendrive`) but not OpenSCENARIO: the engine
//! resolves waypoint positions to road coordinates and decides what an entity without a
//! route does at a junction. It only plans routes and answers questions about them
//! (route s ↔ road s, which road follows at a junction).

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod cost;
mod error;
mod route;
mod search;
mod waypoint;

pub use cost::LANE_CHANGE_COST_M;
pub use error::Error;
pub use route::{Leg, NextRoad, Route, RoutePoint, MAX_WAYPOINTS};
pub use waypoint::{Strategy, Waypoint};

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

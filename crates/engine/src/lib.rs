//! `engine`: runs a resolved OpenSCENARIO scenario on an OpenDRIVE road network at a fixed step
//! and returns what happened — every entity's state at every step, the storyboard's state
//! transitions, and warnings for whatever it could not do.
//!
//! It knows the `openscenario` model and the `opendrive` road network, and nothing of CommonRoad.
//! Behaviour follows the ASAM standard and, where the standard leaves room, esmini 3.6 (the
//! reference traces): see `run` for the order of one frame.
//!
//! Module map, top-down: `run` (the loop: a frame at a time, `Simulation`) · `setup` (the run
//! state built from a scenario) · the behaviours that change the state: `storyboard` (element
//! states and transitions), `conditions` (triggers, edges, delays, each condition), `actions`
//! (one file per action), `controllers` (the driver models), `motion` (default controller),
//! `external` (entities driven from outside: closed loop), `ghost` (the ghost the follow
//! controllers run ahead: setup, trail, restarts) · `sim` (the run state,
//! data only; each behaviour keeps what it remembers in its own `state` module, which names no
//! behaviour: `tests/layering.rs`) · below them `roads` (lane geometry, following lanes through
//! junctions), `positions`, `signals` (traffic signals' states), `dynamics`
//! (transition shapes), `entities`, `trace` (the output).

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod actions;
mod angles;
mod attitude;
mod conditions;
mod controllers;
mod dynamics;
mod entities;
pub mod esmini_random;
mod external;
mod ghost;
mod init_order;
mod motion;
mod position_cache;
mod positions;
mod recorded;
mod relative_position;
mod road_references;
mod roads;
mod route_anchors;
mod route_position;
mod rules;
mod run;
mod run_memos;
mod settings;
mod setup;
mod signals;
mod sim;
mod storyboard;
pub mod trace;
mod trajectory_position;
mod values;
mod warning;

pub use diagnostic::Diagnostic;
pub use entities::bounding_boxes;
pub use external::{Chosen, DriverInput, External, ExternalEntity, ExternalState, Input, ScriptedMotion, Source, OUTSIDE_DRIVERS};
pub use recorded::{EnvironmentChange, LightChange};
pub use road_references::road_references;
pub use run::{simulate, simulate_with, Run, Simulation};
pub use settings::{RunControl, Settings};
pub use trace::{EntityTrace, RoadPos, Sample, SignalState, StoryboardEvent, Trace};
pub use warning::Error;

// The README's example is compiled (and run, where it needs no file) with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

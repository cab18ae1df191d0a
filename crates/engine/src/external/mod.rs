//! Entities driven from outside the engine, for closed-loop runs: a planner under test (or an
//! esmini UDP driver client) gives such an entity its state, or driver input, every step,
//! while the storyboard and the driver models react to it.
//!
//! `choice`: which entities (those whose controller needs an outside driver, or those the
//! caller names) · `input`: what the caller gives per step, checked · `driver_vehicle`:
//! esmini's vehicle model for driver input · `driven`: an external entity's run state · `apply`: where in a frame the inputs take
//! effect · `overridden`: what the storyboard's motion actions do to such an entity (esmini's
//! rules for a controller in override mode).

pub(crate) mod apply;
pub(crate) mod choice;
pub(crate) mod driven;
pub(crate) mod driver_vehicle;
pub(crate) mod input;
pub(crate) mod overridden;

pub use choice::{Chosen, External, ExternalEntity, ScriptedMotion, Source, OUTSIDE_DRIVERS};
pub use input::{DriverInput, ExternalState, Input};

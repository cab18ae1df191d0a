//! SynchronizeAction and its tolerances.

mod basic;
mod tolerance;

//! SynchronizeAction and its tolerances.

mod basic;
mod master_standing;
mod tolerance;

//! commonroad

//! The tests of `osi`, one binary: a module per feature.

mod common;
mod corpus_commonroad;
mod esmini_agreement;
mod follow_trajectory;
mod framing;
mod generated;
mod negative_throttle;

/// Tests that use esmini's fixed ports (48198, 53995, …) take turns.
pub static UDP_PORTS: std::sync::Mutex<()> = std::sync::Mutex::new(());

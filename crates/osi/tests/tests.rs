//! The tests of `osi`, one binary: a module per feature.

mod generated;

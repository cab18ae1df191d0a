//! difftest's tests, one binary: the generator (determinism, every scenario valid for the
//! schema and for osc2cr), the coverage table, what esmini quits on and is never written, and a handful of scenarios against esmini.

mod common;
mod coverage_table;
mod esmini_agreement;
mod esmini_limits;
mod esmini_log;
mod generator;

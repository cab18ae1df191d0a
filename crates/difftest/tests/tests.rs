//! difftest's tests, one binary: the generator (determinism, every scenario valid for the
//! schema and for osc2cr), the coverage table, and a handful of scenarios against esmini.

mod common;
mod coverage_table;
mod esmini_agreement;
mod generator;

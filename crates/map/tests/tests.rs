//! The lanelet conversion's tests, one binary: exact bounds, driving direction and topology,
//! signals and intersections, hostile geometry, and every corpus map through `cr_check.py`.

mod common;

mod bounds_exact;
mod corpus_cr_check;
mod direction_and_topology;
mod hostile;
mod signals_and_intersections;

//! Loading: every corpus file, malformed and mutated input, and how references resolve.

mod corpus;
mod fuzz;
mod malformed;
mod resolution;

//! `osc2cr convert`: the example and exit codes, the corpus, the 2024 format, strict input,
//! hostile input, pictures, resuming and sharding a batch.

mod basic;
mod commonroad_2024;
mod corpus;
mod hostile_inputs;
mod render;
mod resume;
mod shard;
mod strict_input;

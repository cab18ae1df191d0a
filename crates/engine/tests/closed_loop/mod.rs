//! Entities driven from outside: each kind of input, reactions, replays of the open-loop run.

mod inputs;
mod reactivity;
mod replay;

//! The engine's tests, one binary whose modules are its features: `actions/`, `conditions/`,
//! `controllers/`, `roads/`, `positions/`, `ghost/`, `storyboard/`, `closed_loop/`, `signals`,
//! `run` (whole-run properties), `corpus` (every corpus scenario against esmini's traces) and
//! `layering` (the run state below the behaviours). `common` builds the straight fixture road
//! and the cars most of them use; scenarios and roads read from files are in `fixtures/`.

mod common;

mod actions;
mod closed_loop;
mod conditions;
mod controllers;
mod corpus;
mod ghost;
mod layering;
mod positions;
mod roads;
mod run;
mod signals;
mod storyboard;

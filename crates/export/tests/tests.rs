//! The tests of `export`, one binary: a module per feature. The acceptance tests of issue 24
//! (`esmini_round_trip`, `forward_again`; the valid-files criterion is in the CLI's tests) read
//! `../shared` and skip with a notice where it (or esmini) is absent, except under `CI=true`;
//! so does `light_cycles_back` (the lights' cycles after export and convert).

mod common;
mod documents;
mod esmini_round_trip;
mod forward_again;
mod light_cycles_back;
mod slow_road_users;
mod synthetic;

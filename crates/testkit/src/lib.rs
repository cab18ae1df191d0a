//! `testkit` — support for the tests of the other crates (never used by the product):
//! locates the read-only `../shared` directory and its corpus, prepares the two Python
//! environments of the CommonRoad checking tools once per process, and runs `cr_check.py` on
//! batches of files, returning its JSON findings as data, and compares the CommonRoad 2020a and
//! 2024 renderings of a conversion with commonroad-io (`py/compare_2024.py`), and finds the
//! shared esmini binaries the oracle comparisons run; and writes the OpenSCENARIO texts the
//! tests of several crates need alike; gives tests scratch directories that go away with them and pipes to write into.
//!
//! It knows the layout of `../shared/tools` and nothing of the converter's crates.

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

mod compare_2024;
mod cr_check;
mod esmini;
mod fifo;
mod generated;
mod python;
mod scratch_dir;
mod shared;
mod xosc;

pub use compare_2024::{compare_2024, Case2024, Comparison2024};
pub use cr_check::{cr_check, CrCheckResult, Finding};
pub use esmini::{esmini, esmini_command};
pub use fifo::Fifo;
pub use generated::{assert_generated, rs_files};
pub use python::{python_envs, PyEnvs};
pub use scratch_dir::ScratchDir;
pub use shared::{compared_scenarios, corpus_files, files_with_ext, shared_dir, workspace_root};
pub use xosc::{stochastic_set, VEHICLE};

//! The `osc2cr` binary's tests, one test binary whose modules are its commands: `convert/`,
//! `check/`, `render/`, `export/`, `map`, `simulate`, `serve_udp`; `messages` (each failure says its real
//! cause, in every command) and `readme` (the README's commands run as written); then
//! `python_package/` (the wheel as a user installs it), `evaluation` (the paper's evaluation
//! script), `packaging` (every crate packs for crates.io) and `workspace` (every test file of
//! the workspace is compiled). `common`
//! runs the binary and walks the files it writes; inputs that are not in the corpus are in
//! `data/`.

mod common;

mod check;
mod convert;
mod evaluation;
mod export;
mod map;
mod messages;
mod packaging;
mod python_package;
mod readme;
mod render;
mod serve_osi;
mod serve_udp;
mod simulate;
mod workspace;

//! `osc2cr export`, the way back (CommonRoad to OpenSCENARIO + OpenDRIVE): the command line as a
//! user runs it, and every file it writes valid against the ASAM schemas.

use std::path::PathBuf;

mod command_line;
mod valid_files;

/// The CommonRoad scenarios of `../shared`, if it is there.
fn commonroad_scenarios() -> Option<PathBuf> {
    testkit::shared_dir().map(|s| s.join("commonroad-scenarios"))
}

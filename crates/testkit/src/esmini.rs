//! esmini 3.6.0 of the shared tools, the oracle the tests compare with: where its binaries are,
//! whether they run here, and the headless command line every comparison starts from.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::shared::shared_dir;

/// `tools/esmini/bin/esmini-3.6.0` of the shared directory (`osi`: `esmini-3.6.0-osi`, the
/// build that writes OSI), if it runs here (`--version` starts it).
///
/// Not running: panics when the environment variable `CI` is set (a CI run must not silently
/// skip), otherwise prints a notice on stderr and returns `None` so the test can return early.
pub fn esmini(osi: bool) -> Option<PathBuf> {
    let bin = shared_dir()?.join(if osi { "tools/esmini/bin/esmini-3.6.0-osi" } else { "tools/esmini/bin/esmini-3.6.0" });
    if bin.is_file() && Command::new(&bin).arg("--version").output().is_ok() {
        return Some(bin);
    }
    if std::env::var_os("CI").is_some() {
        panic!("esmini {} does not run here (CI is set, so tests that need it fail)", bin.display());
    }
    // testkit serves tests: a skipped test's notice to whoever runs them is its one output
    #[allow(clippy::print_stderr)]
    {
        eprintln!("notice: esmini {} does not run here; skipping this test", bin.display());
    }
    None
}

/// `bin --headless --fixed_timestep step --osc xosc`, its standard output and error discarded:
/// the caller adds its logging options and spawns it.
pub fn esmini_command(bin: &Path, step: f64, xosc: &Path) -> Command {
    let mut c = Command::new(bin);
    c.args(["--headless", "--fixed_timestep", &step.to_string(), "--osc"]).arg(xosc).stdout(Stdio::null()).stderr(Stdio::null());
    c
}

//! The two Python environments of `../shared/tools/setup-venvs.sh`, created once per process
//! under `<workspace>/target/py`. A file lock (`target/py.lock`) keeps several test processes
//! (or people) from building the same environments at the same time; the script itself keeps
//! finished environments, so running it again is cheap.

use std::fs::OpenOptions;
use std::path::PathBuf;
use std::process::Command;
use std::sync::OnceLock;

use crate::shared::{shared_dir, workspace_root};

/// Interpreters of the two environments.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PyEnvs {
    /// commonroad-io 2026.1 + lxml: runs `cr_check.py`.
    pub cr: PathBuf,
    /// commonroad-io 2024.3 + drivability checker + CriMe: `--extra-python`.
    pub crd: PathBuf,
}

static ENVS: OnceLock<Result<PyEnvs, String>> = OnceLock::new();

/// Creates the environments if needed (once per process) and returns their interpreters.
/// Errors say what failed (no shared directory, the script's output).
pub fn python_envs() -> Result<PyEnvs, String> {
    ENVS.get_or_init(setup).clone()
}

fn setup() -> Result<PyEnvs, String> {
    let shared = shared_dir().ok_or("shared directory not found (set OSC2CR_SHARED)")?;
    let target = workspace_root().join("target");
    let py_dir = target.join("py");
    std::fs::create_dir_all(&target).map_err(|e| format!("cannot create {}: {e}", target.display()))?;
    let lock_path = target.join("py.lock");
    let lock = OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .open(&lock_path)
        .map_err(|e| format!("cannot open lock file {}: {e}", lock_path.display()))?;
    lock.lock().map_err(|e| format!("cannot lock {}: {e}", lock_path.display()))?;
    let script = shared.join("tools/setup-venvs.sh");
    let out = Command::new("bash").arg(&script).arg(&py_dir).output().map_err(|e| format!("cannot run bash {}: {e}", script.display()));
    // the lock is released when `lock` is dropped, also on the error paths
    let out = out?;
    if !out.status.success() {
        return Err(format!(
            "bash {} {} failed ({}):\n{}{}",
            script.display(),
            py_dir.display(),
            out.status,
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    drop(lock);
    let envs = PyEnvs { cr: py_dir.join("cr/bin/python"), crd: py_dir.join("crd/bin/python") };
    for p in [&envs.cr, &envs.crd] {
        if !p.exists() {
            return Err(format!("{} missing after setup-venvs.sh", p.display()));
        }
    }
    Ok(envs)
}

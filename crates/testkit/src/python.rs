//! The two Python environments of `../shared/tools/setup-venvs.sh`, created once per process
//! under `<workspace>/target/py` as that script makes them (a venv, its requirements file
//! installed, the file copied to `.ready`), but both at once: pip spends most of a clean
//! checkout's minute and a half unpacking on one core, and the tests waiting for the
//! environments keep the other idle. A file lock (`target/py.lock`) keeps several test
//! processes (or people) from building the same environments at the same time; a finished
//! environment is kept, so asking again is cheap, and the script finds it finished too.

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
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
/// Errors say what failed (no shared directory, pip's output).
pub fn python_envs() -> Result<PyEnvs, String> {
    ENVS.get_or_init(setup).clone()
}

fn setup() -> Result<PyEnvs, String> {
    let shared = shared_dir().ok_or("shared directory not found (set OSC2CR_SHARED)")?;
    let target = workspace_root().join("target");
    let py_dir = target.join("py");
    std::fs::create_dir_all(&py_dir).map_err(|e| format!("cannot create {}: {e}", py_dir.display()))?;
    let lock_path = target.join("py.lock");
    let lock = OpenOptions::new()
        .create(true)
        .truncate(false)
        .write(true)
        .open(&lock_path)
        .map_err(|e| format!("cannot open lock file {}: {e}", lock_path.display()))?;
    lock.lock().map_err(|e| format!("cannot lock {}: {e}", lock_path.display()))?;
    let tools = shared.join("tools");
    let made: Vec<Result<(), String>> = std::thread::scope(|scope| {
        let jobs: Vec<_> = [("cr", "requirements-cr.txt"), ("crd", "requirements-crd.txt")]
            .into_iter()
            .map(|(name, req)| {
                let (req, dir) = (tools.join(req), py_dir.join(name));
                scope.spawn(move || make_env(&dir, &req))
            })
            .collect();
        jobs.into_iter().map(|j| j.join().unwrap_or_else(|_| Err("an environment's thread panicked".into()))).collect()
    });
    // the lock is released when `lock` is dropped, also on the error paths
    drop(lock);
    made.into_iter().collect::<Result<Vec<()>, String>>()?;
    let envs = PyEnvs { cr: py_dir.join("cr/bin/python"), crd: py_dir.join("crd/bin/python") };
    for p in [&envs.cr, &envs.crd] {
        if !p.exists() {
            return Err(format!("{} missing after its environment was made", p.display()));
        }
    }
    Ok(envs)
}

/// One environment as setup-venvs.sh's `make_env` makes it: kept when its `.ready` holds the
/// requirements file's bytes, else made anew.
fn make_env(dir: &Path, req: &Path) -> Result<(), String> {
    let wanted = std::fs::read(req).map_err(|e| format!("cannot read {}: {e}", req.display()))?;
    let ready = dir.join(".ready");
    if std::fs::read(&ready).ok().as_deref() == Some(wanted.as_slice()) {
        return Ok(());
    }
    let _ = std::fs::remove_dir_all(dir);
    run(Command::new("python3").args(["-m", "venv"]).arg(dir))?;
    run(Command::new(dir.join("bin/pip")).args(["install", "--quiet", "--disable-pip-version-check", "-r"]).arg(req))?;
    std::fs::write(&ready, &wanted).map_err(|e| format!("cannot write {}: {e}", ready.display()))
}

fn run(cmd: &mut Command) -> Result<(), String> {
    let out = cmd.output().map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    if out.status.success() {
        Ok(())
    } else {
        Err(format!("{cmd:?} failed ({}):\n{}{}", out.status, String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)))
    }
}

//! What the tests share: the shared data and esmini (skipping with a notice where absent,
//! failing under CI), the Python environment with the osi3 bindings (created under
//! `target/py/osi`, once per process, under a file lock), osc2cr's OSI trace of a scenario, and
//! esmini's scripts taken from the esmini mirror into `target/`.

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// osi-python's version the tests read OSI with (the package index's; it reads OSI 3.5 too).
const OSI_PYTHON: &str = "osi-python==3.8.0";

pub(crate) fn ci() -> bool {
    std::env::var_os("CI").is_some()
}

/// Skips (returns `None`) with a notice, or fails under CI.
pub(crate) fn absent<T>(what: &str) -> Option<T> {
    assert!(!ci(), "{what} (CI is set, so this test fails instead of skipping)");
    eprintln!("notice: {what}; skipping this test");
    None
}

pub(crate) fn shared() -> Option<PathBuf> {
    testkit::shared_dir()
}

pub(crate) fn target() -> PathBuf {
    testkit::workspace_root().join("target")
}

/// A fresh work folder under `target/osi-tests`.
pub(crate) fn work_dir(name: &str) -> PathBuf {
    let d = target().join("osi-tests").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("work folder");
    d
}

static PYTHON: OnceLock<Result<PathBuf, String>> = OnceLock::new();

fn make_venv() -> Result<PathBuf, String> {
    let py_dir = target().join("py");
    std::fs::create_dir_all(&py_dir).map_err(|e| e.to_string())?;
    let lock = OpenOptions::new().create(true).truncate(false).write(true).open(py_dir.join("osi.lock")).map_err(|e| e.to_string())?;
    lock.lock().map_err(|e| e.to_string())?;
    let venv = py_dir.join("osi");
    let python = venv.join("bin/python");
    let ready = venv.join(".osc2cr-ready");
    if std::fs::read_to_string(&ready).ok().as_deref() != Some(OSI_PYTHON) {
        let run = |cmd: &mut Command| -> Result<(), String> {
            let out = cmd.output().map_err(|e| format!("{cmd:?}: {e}"))?;
            if out.status.success() {
                Ok(())
            } else {
                Err(format!("{cmd:?} failed: {}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr)))
            }
        };
        run(Command::new("python3").args(["-m", "venv"]).arg(&venv))?;
        run(Command::new(&python).args(["-m", "pip", "install", "-q", OSI_PYTHON]))?;
        std::fs::write(&ready, OSI_PYTHON).map_err(|e| e.to_string())?;
    }
    Ok(python)
}

/// The interpreter of the environment with the osi3 bindings.
pub(crate) fn python() -> PathBuf {
    PYTHON.get_or_init(make_venv).clone().unwrap_or_else(|e| panic!("the osi3 environment: {e}"))
}

/// Runs `script` (in `tests/py`) with `args`; its stdout.
pub(crate) fn run_py(script: &str, args: &[&Path]) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/py").join(script);
    let out = Command::new(python()).arg(&path).args(args).output().expect("python runs");
    assert!(out.status.success(), "{script} failed:\n{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The scenario file `path` loaded, its road network, and osc2cr's run of it (0.01 s, 60 s).
pub(crate) fn run(path: &Path) -> (openscenario::Scenario, Option<opendrive::RoadNetwork>, engine::Trace) {
    let loaded = openscenario::load(path, &openscenario::LoadOptions::default()).expect("the scenario loads");
    let openscenario::Content::Scenario(scenario) = loaded.content else { panic!("{} is not a scenario", path.display()) };
    let roads = scenario.road_network.logic_file.as_ref().map(|p| opendrive::load(p).expect("the road network loads").network);
    let settings = engine::Settings { step: 0.01, max_time: 60.0 };
    let run = engine::simulate(&scenario, roads.as_ref(), &settings).expect("the run");
    (*scenario, roads, run.trace)
}

/// osc2cr's OSI trace of the scenario file `path`, written to `out`; the number of messages.
pub(crate) fn write_trace(path: &Path, out: &Path) -> usize {
    let (scenario, roads, trace) = run(path);
    let (frames, _) = osi::trace_frames(&scenario, roads.as_ref(), &trace);
    osi::trace_file::write(out, &frames).expect("the trace file is written");
    frames.len()
}

/// The esmini mirror's `paths` (files or folders of its v3.6.0 tree) extracted under `into`
/// (`None`, with a notice, where the mirror is absent). The mirror is a developer's copy of
/// esmini's source, never part of CI's `../shared`, so its absence skips even under CI.
pub(crate) fn esmini_files(into: &Path, paths: &[&str]) -> Option<PathBuf> {
    let mirror = std::env::var_os("OSC2CR_ESMINI_MIRROR").map(PathBuf::from).unwrap_or_else(|| PathBuf::from("/work/.mirror/esmini+esmini/repo"));
    if !mirror.is_dir() {
        eprintln!("skipped: esmini's source mirror {} is absent (set OSC2CR_ESMINI_MIRROR)", mirror.display());
        return None;
    }
    let archive = Command::new("git").arg("-C").arg(&mirror).args(["archive", "--format=tar", "v3.6.0"]).args(paths).output().expect("git runs");
    if !archive.status.success() {
        return absent(&format!("git archive of esmini v3.6.0 failed: {}", String::from_utf8_lossy(&archive.stderr)));
    }
    std::fs::create_dir_all(into).expect("folder");
    let tar = into.join("esmini.tar");
    std::fs::write(&tar, &archive.stdout).expect("tar written");
    let ok = Command::new("tar").arg("-xf").arg(&tar).arg("-C").arg(into).status().expect("tar runs").success();
    assert!(ok, "tar -xf {}", tar.display());
    Some(into.to_path_buf())
}

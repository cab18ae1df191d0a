//! `src/protobuf/sign_names.rs` is exactly what `tools/extract_commonroad_sign_names.py` writes
//! from the `traffic_sign.py` of commonroad-io 2026.1: the test runs the generator on the copy
//! installed in testkit's `cr` environment (which pins 2026.1) and compares the bytes, so the
//! checked-in table cannot drift from its source or be edited by hand. Skipped with a notice when
//! `../shared` is absent (it holds the environments' requirements).

use std::path::PathBuf;
use std::process::Command;

/// Runs `python -c CODE` in the `cr` environment and returns its standard output, trimmed.
fn python(py: &std::path::Path, code: &str) -> String {
    let out = Command::new(py).arg("-c").arg(code).output().expect("the cr environment's python runs");
    assert!(out.status.success(), "python -c {code}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

#[test]
fn the_checked_in_sign_names_are_the_generators_output_for_commonroad_io_2026_1() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let envs = testkit::python_envs().unwrap_or_else(|e| panic!("Python environments unavailable: {e}"));
    assert_eq!(python(&envs.cr, "import importlib.metadata as m; print(m.version('commonroad-io'))"), "2026.1", "the table is of commonroad-io 2026.1");
    // the folder holding `commonroad/`, found without importing the package
    let site = python(&envs.cr, "import importlib.util, os; print(os.path.dirname(importlib.util.find_spec('commonroad').submodule_search_locations[0]))");
    let root = testkit::workspace_root();
    let out = Command::new(&envs.cr).arg(root.join("tools/extract_commonroad_sign_names.py")).arg(&site).output().expect("the generator runs");
    assert!(out.status.success(), "extract_commonroad_sign_names.py {site}: {}", String::from_utf8_lossy(&out.stderr));
    let checked_in = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src/protobuf/sign_names.rs");
    let have = std::fs::read(&checked_in).expect("sign_names.rs");
    assert!(
        out.stdout == have,
        "src/protobuf/sign_names.rs is not the generator's output; regenerate it with \
         tools/extract_commonroad_sign_names.py {site} > crates/commonroad/src/protobuf/sign_names.rs"
    );
    // the table is not empty: Germany's (and China's) speed limit 274 is there under its 2024 name
    let text = String::from_utf8_lossy(&have);
    assert!(text.contains("\"DEU\"") && text.contains("(\"274\", \"MAX_SPEED\")"), "274 is MAX_SPEED");
}

//! The acceptance criterion "valid files" of issue 24: every `.xosc` written — of the CommonRoad
//! scenarios and of every corpus conversion (five variations per parameter distribution), in
//! OpenSCENARIO 1.3 (default ego and `--ego-controller external`) and 1.0 — validates against the
//! ASAM schema of its version in `../shared/spec` (lxml, in a virtual environment under `target/`)
//! and `osc2cr check` finds no error in it.

use crate::common::*;

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::process::Command;

/// An environment with lxml for the schema checks, under `target/py` (made once, kept).
fn lxml_python() -> PathBuf {
    let py = testkit::workspace_root().join("target/py");
    std::fs::create_dir_all(&py).expect("target/py");
    let lock = OpenOptions::new().create(true).truncate(false).write(true).open(py.join("export-xsd.lock")).expect("lock file");
    lock.lock().expect("lock");
    let venv = py.join("export-xsd");
    let python = venv.join("bin/python");
    let ok = |c: &mut Command| c.status().is_ok_and(|s| s.success());
    if !ok(Command::new(&python).args(["-c", "import lxml"])) {
        let _ = std::fs::remove_dir_all(&venv);
        assert!(ok(Command::new("python3").args(["-m", "venv"]).arg(&venv)), "python3 -m venv");
        assert!(ok(Command::new(&python).args(["-m", "pip", "install", "--quiet", "--disable-pip-version-check", "lxml==5.3.0"])), "pip install lxml");
    }
    python
}

/// Every `.xosc` below `dir` against its version's XSD: the files with errors and their first error.
fn schema_errors(python: &Path, spec: &Path, dir: &Path) -> Vec<String> {
    let files: Vec<PathBuf> = files(dir).into_iter().filter(|p| p.extension().is_some_and(|e| e == "xosc")).map(|p| dir.join(p)).collect();
    assert!(!files.is_empty(), "no .xosc under {}", dir.display());
    let script = testkit::workspace_root().join("crates/export/tests/py/validate_xosc.py");
    let mut errors = Vec::new();
    for chunk in files.chunks(200) {
        let out = Command::new(python).arg(&script).arg(spec).args(chunk).output().expect("python runs");
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let json: serde_json::Map<String, serde_json::Value> = serde_json::from_slice(&out.stdout).expect("json");
        for (file, errs) in json {
            if let Some(first) = errs.as_array().and_then(|a| a.first()) {
                errors.push(format!("{file}: {first}"));
            }
        }
    }
    errors
}

/// `osc2cr check --json` on a folder: its errors.
fn check_errors(dir: &Path) -> Vec<String> {
    let r = osc2cr(&["check", "--json", s(dir)]);
    let findings: Vec<serde_json::Value> = serde_json::from_slice(&r.stdout).expect("check --json");
    findings.iter().filter(|f| f["severity"] == "error").map(|f| format!("{}:{}: {}", f["file"], f["line"], f["message"])).collect()
}

#[test]
fn every_exported_scenario_validates_and_checks_clean() {
    let Some(shared) = testkit::shared_dir() else { return };
    let python = lxml_python();
    let spec = shared.join("spec");
    // the corpus conversions (2020a) and the CommonRoad scenarios; five variations per
    // distribution, as in convert/corpus.rs: the others (half the files) take the same path
    let corpus = tmp("export_cli", "corpus-commonroad");
    let r = osc2cr(&["convert", s(&shared.join("corpus")), "-o", s(&corpus), "-j", "2", "--max-variations", "5"]);
    assert!(r.status.code().is_some_and(|c| c <= 1), "{}", String::from_utf8_lossy(&r.stderr));
    let inputs = [shared.join("commonroad-scenarios"), corpus];
    let variants: [(&str, &[&str]); 3] = [("osc13", &[]), ("osc13-external", &["--ego-controller", "external"]), ("osc10", &["--osc", "1.0"])];
    for (name, extra) in variants {
        let out = tmp("export_cli", &format!("valid-{name}"));
        let mut args = vec!["export", s(&inputs[0]), s(&inputs[1]), "-o", s(&out), "-j", "2"];
        args.extend_from_slice(extra);
        let r = osc2cr(&args);
        assert_ok(&r);
        let n = files(&out).iter().filter(|p| p.extension().is_some_and(|e| e == "xosc")).count();
        let schema = schema_errors(&python, &spec, &out);
        let check = check_errors(&out);
        eprintln!("valid files ({name}): {n} scenarios, {} invalid against the schema, {} check errors", schema.len(), check.len());
        assert!(schema.is_empty(), "{name}: files the schema refuses:\n{}", schema.join("\n"));
        assert!(check.is_empty(), "{name}: osc2cr check finds errors:\n{}", check.join("\n"));
    }
}

//! `osc2cr export` as a user runs it: `--help`, a batch that goes on past a bad file (exit
//! status, summary table, JSON report, maps at the top, written once and shared), the same
//! bytes on a second run and whatever `-j`, no temporary file left; and the acceptance
//! criterion "valid files": every `.xosc` written — of the CommonRoad scenarios and of every
//! corpus conversion, in OpenSCENARIO 1.3 (default ego and `--ego-controller external`) and
//! 1.0 — validates against the ASAM schema of its version in `../shared/spec` (lxml, in a
//! virtual environment under `target/`) and `osc2cr check` finds no error in it.

mod common;
use common::*;

use std::fs::OpenOptions;
use std::path::{Path, PathBuf};
use std::process::Command;

fn commonroad_scenarios() -> Option<PathBuf> {
    testkit::shared_dir().map(|s| s.join("commonroad-scenarios"))
}

#[test]
fn help_explains_the_command() {
    let r = osc2cr(&["export", "--help"]);
    assert_ok(&r);
    let help = String::from_utf8_lossy(&r.stdout);
    for needle in [
        "2018b",
        "2024",
        "NAME-SC.pb",
        "--osc",
        "1.0",
        "--ego-controller",
        "external",
        "--play-to-end",
        "--report",
        "-j",
        "named by its",
        "traffic-signal controllers",
    ] {
        assert!(help.contains(needle), "--help names {needle:?}:\n{help}");
    }
}

#[test]
fn a_batch_goes_on_past_a_bad_file_and_writes_the_same_bytes_again() {
    let Some(scenarios) = commonroad_scenarios() else { return };
    let bad_dir = tmp("export_cli", "bad-input");
    let bad = bad_dir.join("broken.xml");
    std::fs::write(&bad, "<commonRoad commonRoadVersion=\"2020a\"><lanelet id=\"x\"").expect("write");
    let out = tmp("export_cli", "batch");
    let report = bad_dir.join("report.json");
    let r = osc2cr(&["export", s(&scenarios), s(&bad), "-o", s(&out), "--report", s(&report), "-j", "2"]);
    assert_eq!(r.status.code(), Some(1), "a partial batch: {}", String::from_utf8_lossy(&r.stderr));
    let stderr = String::from_utf8_lossy(&r.stderr);
    assert!(stderr.contains("failed") && stderr.contains("broken.xml"), "{stderr}");
    let table = String::from_utf8_lossy(&r.stdout);
    assert!(table.contains("scenarios") && table.contains("exported") && table.contains("all"), "{table}");

    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).expect("report")).expect("json");
    let scenarios_n = json["scenarios"].as_array().expect("scenarios").len();
    assert_eq!(json["failed"], 1);
    assert_eq!(json["exported"].as_u64(), Some(scenarios_n as u64 - 1));
    // every map is at the top of the output folder, written once, and names what uses it
    let maps = json["maps"].as_array().expect("maps");
    assert!(!maps.is_empty());
    let used: u64 = maps.iter().map(|m| m["scenarios"].as_u64().unwrap_or(0)).sum();
    let with_map = json["scenarios"].as_array().expect("scenarios").iter().filter(|s| s["map"].is_string()).count();
    assert_eq!(used, with_map as u64);
    for m in maps {
        let name = m["file"].as_str().expect("file");
        assert!(out.join(name).is_file(), "{name} at the top");
    }
    // scenarios on the same lanelet network share one map (the test_reading_* files do)
    assert!(maps.iter().any(|m| m["scenarios"].as_u64().unwrap_or(0) >= 2), "a map shared: {maps:?}");
    assert!(maps.len() < with_map, "{} maps for {with_map} scenarios", maps.len());
    // a scenario in a sub-folder names its map relative to itself
    let tutorial = std::fs::read_to_string(out.join("tutorials/ZAM_Tutorial-1_1_T-1.xosc")).expect("tutorial written");
    assert!(tutorial.contains("<LogicFile filepath=\"../ZAM_"), "relative map path");

    let first = contents(&out);
    assert!(first.keys().all(|p| !p.to_string_lossy().ends_with(".tmp")), "no temporary file left");
    let again = tmp("export_cli", "batch-again");
    let r = osc2cr(&["export", s(&scenarios), "-o", s(&again), "-j", "1"]);
    assert_ok(&r);
    assert_eq!(contents(&again), first, "the same input gives the same bytes, whatever -j");
}

#[test]
fn one_bad_file_is_bad_input() {
    let dir = tmp("export_cli", "one-bad");
    let bad = dir.join("nothing.xml");
    std::fs::write(&bad, "not xml").expect("write");
    let r = osc2cr(&["export", s(&bad), "-o", s(&dir.join("out"))]);
    assert_eq!(r.status.code(), Some(2), "{}", String::from_utf8_lossy(&r.stderr));
}

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
    // the corpus conversions (2020a) and the CommonRoad scenarios
    let corpus = tmp("export_cli", "corpus-commonroad");
    let r = osc2cr(&["convert", s(&shared.join("corpus")), "-o", s(&corpus), "-j", "2"]);
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

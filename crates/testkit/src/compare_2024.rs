//! Runs `py/compare_2024.py` with commonroad-io 2026.1: each conversion's 2020a file and its
//! three 2024 files are read by the same library and compared object by object (the script's
//! docstring says what is compared and how). One result per case, in the order given.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

use crate::python::python_envs;
use crate::shared::workspace_root;

/// The two renderings of one conversion.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Case2024 {
    pub xml: PathBuf,
    pub map: PathBuf,
    pub scenario: PathBuf,
    pub dynamic: PathBuf,
}

/// The comparison of one case.
#[derive(Debug, Clone, PartialEq)]
pub struct Comparison2024 {
    pub xml: PathBuf,
    /// Both read, and no difference.
    pub ok: bool,
    /// The first differences, each naming the object and the field.
    pub differences: Vec<String>,
    pub n_differences: u64,
    /// Objects compared, by kind (lanelets, trajectory states, …).
    pub counted: Value,
    /// A reader's exception, when one failed.
    pub error: Option<String>,
}

impl Comparison2024 {
    /// For assertion messages.
    pub fn summary(&self) -> String {
        format!(
            "{}: {} difference(s){}\n  {}",
            self.xml.display(),
            self.n_differences,
            self.error.as_ref().map(|e| format!("\nreader error:\n{e}")).unwrap_or_default(),
            self.differences.join("\n  ")
        )
    }
}

/// Python processes a comparison runs at most (each reads its share of the cases).
const PROCESSES: usize = 2;

/// Compares every case (the cases split over at most two Python processes, results in the
/// order of `cases`).
///
/// Test support: panics with a clear message when the tools cannot run.
pub fn compare_2024(cases: &[Case2024], work_dir: &Path) -> Vec<Comparison2024> {
    let envs = python_envs().unwrap_or_else(|e| panic!("compare_2024: Python environments unavailable: {e}"));
    std::fs::create_dir_all(work_dir).unwrap_or_else(|e| panic!("cannot create {}: {e}", work_dir.display()));
    let per = cases.len().div_ceil(PROCESSES).max(1);
    std::thread::scope(|scope| {
        let parts: Vec<_> = cases
            .chunks(per)
            .enumerate()
            .map(|(i, chunk)| {
                let python = envs.cr.clone();
                scope.spawn(move || run_part(&python, chunk, &work_dir.join(format!("cases-2024-{i}.json"))))
            })
            .collect();
        parts.into_iter().flat_map(|p| p.join().unwrap_or_else(|_| panic!("compare_2024: a part panicked"))).collect()
    })
}

fn run_part(python: &Path, cases: &[Case2024], cases_file: &Path) -> Vec<Comparison2024> {
    let list: Vec<Value> = cases
        .iter()
        .map(|c| {
            serde_json::json!({
                "xml": c.xml, "map": c.map, "scenario": c.scenario, "dynamic": c.dynamic,
            })
        })
        .collect();
    std::fs::write(cases_file, serde_json::to_vec(&list).expect("json")).unwrap_or_else(|e| panic!("cannot write {}: {e}", cases_file.display()));
    let script = workspace_root().join("crates/testkit/py/compare_2024.py");
    let out =
        Command::new(python).arg(&script).arg(cases_file).output().unwrap_or_else(|e| panic!("cannot run {} {}: {e}", python.display(), script.display()));
    let stdout = String::from_utf8_lossy(&out.stdout);
    if !matches!(out.status.code(), Some(0 | 1)) {
        panic!("compare_2024.py failed ({}):\n{stdout}\n{}", out.status, String::from_utf8_lossy(&out.stderr));
    }
    let lines: Vec<&str> = stdout.lines().filter(|l| l.starts_with('{')).collect();
    assert_eq!(lines.len(), cases.len(), "compare_2024.py printed {} results for {} cases:\n{stdout}", lines.len(), cases.len());
    lines
        .iter()
        .map(|l| {
            let v: Value = serde_json::from_str(l).unwrap_or_else(|e| panic!("not JSON ({e}): {l}"));
            Comparison2024 {
                xml: PathBuf::from(v["xml"].as_str().unwrap_or_default()),
                ok: v["ok"].as_bool().unwrap_or(false),
                differences: v["differences"].as_array().map(|a| a.iter().filter_map(|s| s.as_str().map(String::from)).collect()).unwrap_or_default(),
                n_differences: v["n_differences"].as_u64().unwrap_or(0),
                counted: v["counted"].clone(),
                error: v["error"].as_str().map(String::from),
            }
        })
        .collect()
}

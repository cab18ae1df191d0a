//! Runs `../shared/tools/cr_check.py` (the CommonRoad oracle) on batches of files and parses
//! its output: one JSON object per line and file, in argument order.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

use crate::python::python_envs;
use crate::shared::shared_dir;

/// One finding of cr_check.py (`{"check": …, "msg": …}`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Finding {
    pub check: String,
    pub msg: String,
}

/// cr_check.py's verdict on one file.
#[derive(Debug, Clone, PartialEq)]
pub struct CrCheckResult {
    pub file: PathBuf,
    /// No hard failure (XSD, both readers, semantic checks, requested extra checks).
    pub ok: bool,
    /// Hard failures (listed ones are capped per check by `--max-per-check`).
    pub errors: Vec<Finding>,
    pub warnings: Vec<Finding>,
    /// Uncapped counts per check name.
    pub error_counts: BTreeMap<String, u64>,
    pub warning_counts: BTreeMap<String, u64>,
    /// The whole JSON object (stats, reads, on_road, drivability, …).
    pub json: Value,
}

impl CrCheckResult {
    /// Total number of warnings (uncapped).
    pub fn n_warnings(&self) -> u64 {
        self.warning_counts.values().sum()
    }
    /// Total number of hard failures (uncapped).
    pub fn n_errors(&self) -> u64 {
        self.error_counts.values().sum()
    }
    /// A one-paragraph description for assertion messages.
    pub fn summary(&self) -> String {
        let list = |v: &[Finding]| v.iter().map(|f| format!("  [{}] {}", f.check, f.msg)).collect::<Vec<_>>().join("\n");
        format!(
            "{}: {} ({} errors, {} warnings)\nerrors:\n{}\nwarnings:\n{}",
            self.file.display(),
            if self.ok { "ok" } else { "FAILED" },
            self.n_errors(),
            self.n_warnings(),
            list(&self.errors),
            list(&self.warnings)
        )
    }
}

/// Files per cr_check.py process: one interpreter start-up per batch instead of per file.
const BATCH: usize = 64;

/// Runs `<cr python> <shared>/tools/cr_check.py --extra-python <crd python> EXTRA... FILES...`
/// and returns one result per file, in the order of `files`.
///
/// Test support: panics with a clear message when the tools cannot run (no shared directory,
/// environments failing, unparsable output); callers check [`crate::shared_dir`] first.
pub fn cr_check<P: AsRef<Path>>(files: &[P], extra_args: &[&str]) -> Vec<CrCheckResult> {
    let shared = shared_dir().unwrap_or_else(|| panic!("cr_check: shared directory not found (set OSC2CR_SHARED)"));
    let envs = python_envs().unwrap_or_else(|e| panic!("cr_check: Python environments unavailable: {e}"));
    let script = shared.join("tools/cr_check.py");
    let mut results = Vec::with_capacity(files.len());
    for batch in files.chunks(BATCH) {
        let out = Command::new(&envs.cr)
            .arg(&script)
            .arg("--extra-python")
            .arg(&envs.crd)
            .args(extra_args)
            .args(batch.iter().map(AsRef::as_ref))
            .output()
            .unwrap_or_else(|e| panic!("cannot run {} {}: {e}", envs.cr.display(), script.display()));
        let stdout = String::from_utf8_lossy(&out.stdout);
        // exit 0 = all pass, 1 = some file failed; anything else is a usage error or a crash
        if !matches!(out.status.code(), Some(0 | 1)) {
            panic!("cr_check.py failed ({}):\nstdout:\n{stdout}\nstderr:\n{}", out.status, String::from_utf8_lossy(&out.stderr));
        }
        let lines: Vec<&str> = stdout.lines().filter(|l| l.trim_start().starts_with('{')).collect();
        if lines.len() != batch.len() {
            panic!("cr_check.py printed {} JSON lines for {} files:\n{stdout}\nstderr:\n{}", lines.len(), batch.len(), String::from_utf8_lossy(&out.stderr));
        }
        for (file, line) in batch.iter().zip(lines) {
            let json: Value = serde_json::from_str(line).unwrap_or_else(|e| panic!("cr_check.py output is not JSON ({e}): {line}"));
            results.push(parse(file.as_ref(), json));
        }
    }
    results
}

fn findings(v: &Value) -> Vec<Finding> {
    v.as_array()
        .map(|a| {
            a.iter()
                .map(|f| Finding {
                    check: f.get("check").and_then(Value::as_str).unwrap_or("").to_string(),
                    msg: f.get("msg").and_then(Value::as_str).unwrap_or("").to_string(),
                })
                .collect()
        })
        .unwrap_or_default()
}

fn counts(v: Option<&Value>) -> BTreeMap<String, u64> {
    v.and_then(Value::as_object).map(|m| m.iter().map(|(k, n)| (k.clone(), n.as_u64().unwrap_or(0))).collect()).unwrap_or_default()
}

fn parse(file: &Path, json: Value) -> CrCheckResult {
    let errors = findings(&json["errors"]);
    let warnings = findings(&json["warnings"]);
    let mut error_counts = counts(json.get("finding_counts").and_then(|c| c.get("errors")));
    let mut warning_counts = counts(json.get("finding_counts").and_then(|c| c.get("warnings")));
    // e.g. a missing file has findings but no finding_counts
    for (list, map) in [(&errors, &mut error_counts), (&warnings, &mut warning_counts)] {
        if map.is_empty() {
            for f in list {
                *map.entry(f.check.clone()).or_insert(0) += 1;
            }
        }
    }
    CrCheckResult {
        file: file.to_path_buf(),
        ok: json.get("ok").and_then(Value::as_bool).unwrap_or(false),
        errors,
        warnings,
        error_counts,
        warning_counts,
        json,
    }
}

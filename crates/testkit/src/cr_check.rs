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

/// Runs `<cr python> <shared>/tools/cr_check.py EXTRA... FILES...` and returns one result per
/// file, in the order of `files`, each with the second reader's verdict as cr_check.py's
/// `--extra-python <crd python>` gives it (`extra_reads`, a `read_extra` error when it fails).
///
/// cr_check.py's `--extra-python` starts the other interpreter once per file to read it; over
/// a corpus that start-up (importing commonroad-io) costs three times the checks themselves.
/// So the older interpreter runs once per batch, beside the first, calling the function that
/// worker runs, cr_check.py's `read_with_commonroad_io`, on each file (`SECOND_READER`). With
/// `--drivability`, whose checker may live only in the older environment, cr_check.py gets
/// `--extra-python` as before.
///
/// Test support: panics with a clear message when the tools cannot run (no shared directory,
/// environments failing, unparsable output); callers check [`crate::shared_dir`] first.
pub fn cr_check<P: AsRef<Path>>(files: &[P], extra_args: &[&str]) -> Vec<CrCheckResult> {
    let shared = shared_dir().unwrap_or_else(|| panic!("cr_check: shared directory not found (set OSC2CR_SHARED)"));
    let envs = python_envs().unwrap_or_else(|e| panic!("cr_check: Python environments unavailable: {e}"));
    let script = shared.join("tools/cr_check.py");
    let per_file_worker = extra_args.contains(&"--drivability");
    let mut results = Vec::with_capacity(files.len());
    for batch in files.chunks(BATCH) {
        let batch: Vec<&Path> = batch.iter().map(AsRef::as_ref).collect();
        let mut first = Command::new(&envs.cr);
        first.arg(&script);
        if per_file_worker {
            first.arg("--extra-python").arg(&envs.crd);
        }
        // the two interpreters read the batch side by side
        let tools = script.parent().unwrap_or(Path::new("."));
        let (jsons, second) = std::thread::scope(|scope| {
            let second = (!per_file_worker).then(|| scope.spawn(|| run_batch(Command::new(&envs.crd).arg("-c").arg(SECOND_READER).arg(tools), &batch)));
            let jsons = run_batch(first.args(extra_args), &batch);
            (jsons, second.map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))))
        });
        for (i, (file, mut json)) in batch.iter().zip(jsons).enumerate() {
            if let Some(second) = &second {
                add_second_read(&mut json, &second[i], &envs.crd);
            }
            results.push(parse(file, json));
        }
    }
    results
}

/// The second reader: cr_check.py's per-file `--internal-worker read` (the same quieting of
/// warnings and logging as its `main`), over every file given after the tools folder, one JSON
/// line (the read's verdict) per file.
const SECOND_READER: &str = "import json, logging, sys, warnings
sys.path.insert(0, sys.argv[1])
import cr_check
warnings.simplefilter('ignore')
logging.disable(logging.WARNING)
for path in sys.argv[2:]:
    read, _, _ = cr_check.read_with_commonroad_io(path)
    print(json.dumps(read), flush=True)
";

/// One Python process over `batch` (cr_check.py, or `SECOND_READER`): its JSON line per file,
/// in order.
fn run_batch(cmd: &mut Command, batch: &[&Path]) -> Vec<Value> {
    let out = cmd.args(batch).output().unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e}"));
    let stdout = String::from_utf8_lossy(&out.stdout);
    // exit 0 = all pass, 1 = some file failed; anything else is a usage error or a crash
    if !matches!(out.status.code(), Some(0 | 1)) {
        panic!("cr_check.py failed ({}):\nstdout:\n{stdout}\nstderr:\n{}", out.status, String::from_utf8_lossy(&out.stderr));
    }
    let lines: Vec<&str> = stdout.lines().filter(|l| l.trim_start().starts_with('{')).collect();
    if lines.len() != batch.len() {
        panic!("cr_check.py printed {} JSON lines for {} files:\n{stdout}\nstderr:\n{}", lines.len(), batch.len(), String::from_utf8_lossy(&out.stderr));
    }
    lines.iter().map(|line| serde_json::from_str(line).unwrap_or_else(|e| panic!("cr_check.py output is not JSON ({e}): {line}"))).collect()
}

/// Adds the older interpreter's read of the file (`second`, from `SECOND_READER`) to the first
/// run's `json` as cr_check.py's per-file worker would: under `extra_reads`, and, if it failed,
/// as a `read_extra` error. Like cr_check.py, only where the first reader ran (not for a
/// missing or malformed file).
fn add_second_read(json: &mut Value, second: &Value, python: &Path) {
    if json.get("read").is_none() {
        return;
    }
    let mut read = second.clone();
    read["python"] = Value::String(python.display().to_string());
    if read.get("ok").and_then(Value::as_bool) != Some(true) {
        let msg = format!("commonroad-io {} ({}): {}", read["commonroad_io"].as_str().unwrap_or("?"), python.display(), read["error"].as_str().unwrap_or("?"));
        json["ok"] = Value::Bool(false);
        if let Some(errors) = json.get_mut("errors").and_then(Value::as_array_mut) {
            errors.push(serde_json::json!({"check": "read_extra", "msg": msg}));
        }
        // (a file with a reader has finding counts; `errors` is absent while there are none)
        let n = json["finding_counts"]["errors"]["read_extra"].as_u64().unwrap_or(0);
        json["finding_counts"]["errors"]["read_extra"] = Value::from(n + 1);
        if let Some(n) = json.get("n_errors").and_then(Value::as_u64) {
            json["n_errors"] = Value::from(n + 1);
        }
    }
    json["extra_reads"] = Value::Array(vec![read]);
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

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn first_run() -> Value {
        json!({"file": "a.xml", "ok": true, "read": {"ok": true, "commonroad_io": "2026.1"}, "errors": [], "warnings": [], "finding_counts": {"warnings": {"kinematics": 1}}})
    }

    #[test]
    fn a_second_reader_that_fails_is_a_read_extra_error() {
        let mut j = first_run();
        add_second_read(&mut j, &json!({"ok": false, "commonroad_io": "2024.3", "error": "KeyError: x"}), Path::new("/py/crd"));
        let r = parse(Path::new("a.xml"), j);
        assert!(!r.ok);
        assert_eq!(r.error_counts.get("read_extra"), Some(&1));
        assert_eq!(r.errors, vec![Finding { check: "read_extra".into(), msg: "commonroad-io 2024.3 (/py/crd): KeyError: x".into() }]);
        assert_eq!(r.json["extra_reads"][0]["python"], "/py/crd");
        assert_eq!(r.warning_counts.get("kinematics"), Some(&1));
    }

    #[test]
    fn a_second_reader_that_reads_adds_its_read_only() {
        let mut j = first_run();
        add_second_read(&mut j, &json!({"ok": true, "commonroad_io": "2024.3", "counts": {"lanelets": 3}}), Path::new("/py/crd"));
        let r = parse(Path::new("a.xml"), j);
        assert!(r.ok, "{}", r.summary());
        assert_eq!(r.n_errors(), 0);
        assert_eq!(r.json["extra_reads"][0]["counts"]["lanelets"], 3);
    }

    #[test]
    fn no_second_read_where_the_first_reader_did_not_run() {
        let mut j = json!({"file": "m.xml", "ok": false, "errors": [{"check": "file", "msg": "not found"}]});
        add_second_read(&mut j, &json!({"ok": false, "commonroad_io": "2024.3", "error": "FileNotFoundError"}), Path::new("/py/crd"));
        let r = parse(Path::new("m.xml"), j);
        assert_eq!(r.error_counts.get("file"), Some(&1));
        assert_eq!(r.n_errors(), 1);
        assert!(r.json.get("extra_reads").is_none());
    }
}

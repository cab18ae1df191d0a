//! `osc2cr check` against the ASAM OpenSCENARIO API's own expectations.
//!
//! `data/checker_suite_expectations.tsv` records, for each broken test file of
//! `../shared/checker-suite/`, the messages the API's C++ tests (`TestFilesV1_*.cpp`,
//! `TestRangeCheckerV1_*.cpp`, `TestDeprecatedV1_*.cpp`, … in RA-Consulting-GmbH/openscenario.api.test)
//! require, with severity and line (extracted by `tools/extract_checker_expectations.py`). A file
//! is judged by the expectations of the newest API version that tests it (older readers word the
//! same problems differently and at other columns). An expected message is found when `check`
//! reports a finding of the same severity class on the same line, each finding answering at most
//! one expectation. The files the API reads without an error must give none here either.

use crate::common::*;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// Parameter values the API's tests inject (`TestInjectedParametersV1_*`), per file name prefix.
const INJECTED: &[(&str, &[&str])] = &[
    (
        "DoubleLaneChangerInjectedParams",
        &[
            "testBoolean=wrongBoolean",
            "testInteger=wrongInteger",
            "testUnsignedInt=wrongUnsignedIntValue",
            "testDateTime=wrongDateTimeValue",
            "testUnsignedShort=wrongUnsingedShortValue",
            "testDouble=wrongDoubleValue",
            "notDefined=wrongBoolean",
        ],
    ),
    ("DoubleLaneChanger1_", &["notDefined=wrongBoolean"]),
    ("DoubleLaneChanger.xosc", &["notDefined=wrongBoolean"]),
];

/// Expectations that are not the API's checks but a rule one test defines for itself
/// (TestVersionChecker adds a custom "must be version 1.0" rule).
fn is_test_specific(tests: &str) -> bool {
    tests.contains("VersionChecker")
}

struct Expected {
    severity: &'static str,
    line: u64,
    message: String,
}

fn newest_api_version(tests: &str) -> u32 {
    tests.split(',').filter_map(|t| t.split("V1_").nth(1).and_then(|v| v.chars().next()).and_then(|c| c.to_digit(10))).max().unwrap_or(0)
}

fn expectations() -> BTreeMap<String, Vec<Expected>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/checker_suite_expectations.tsv");
    let text = std::fs::read_to_string(path).expect("expectations");
    let mut rows: BTreeMap<String, Vec<(u32, Expected)>> = BTreeMap::new();
    for line in text.lines().skip(1) {
        let f: Vec<&str> = line.split('\t').collect();
        let [file, severity, line_no, _col, message, tests] = f[..] else { panic!("bad row {line}") };
        if is_test_specific(tests) {
            continue;
        }
        let severity = match severity {
            "ERROR" | "FATAL" => "error",
            "WARNING" => "warning",
            _ => "info",
        };
        let e = Expected { severity, line: line_no.parse().expect("line"), message: message.to_string() };
        rows.entry(file.to_string()).or_default().push((newest_api_version(tests), e));
    }
    rows.into_iter()
        .map(|(file, es)| {
            let newest = es.iter().map(|(v, _)| *v).max().unwrap_or(0);
            (file, es.into_iter().filter(|(v, _)| *v == newest).map(|(_, e)| e).collect())
        })
        .collect()
}

fn check_json(file: &Path, params: &[&str]) -> Vec<serde_json::Value> {
    let mut args = vec!["check".to_string(), "--json".to_string(), file.display().to_string()];
    for p in params {
        args.push("--param".into());
        args.push(p.to_string());
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let r = osc2cr(&args);
    let json: serde_json::Value =
        serde_json::from_slice(&r.stdout).unwrap_or_else(|e| panic!("{}: {e}: {}", file.display(), String::from_utf8_lossy(&r.stderr)));
    json.as_array().cloned().unwrap_or_default()
}

#[test]
fn check_finds_the_api_expected_messages_at_their_lines() {
    let Some(shared) = testkit::shared_dir() else { return };
    let suite = shared.join("checker-suite");
    let mut total: HashMap<&str, usize> = HashMap::new();
    let mut found: HashMap<&str, usize> = HashMap::new();
    let mut missed = Vec::new();
    for (file, expected) in expectations() {
        let params = INJECTED.iter().find(|(prefix, _)| file.starts_with(prefix)).map_or(&[][..], |(_, p)| *p);
        let name = Path::new(&file).file_name().and_then(|n| n.to_str()).unwrap_or_default().to_string();
        let findings = check_json(&suite.join(&file), params);
        let mut pool: Vec<(u64, String)> = findings
            .iter()
            .filter(|f| f["file"].as_str().is_some_and(|p| p.ends_with(&name)))
            .map(|f| (f["line"].as_u64().unwrap_or(0), f["severity"].as_str().unwrap_or_default().to_string()))
            .collect();
        for e in expected {
            *total.entry(e.severity).or_default() += 1;
            match pool.iter().position(|(l, s)| *l == e.line && s == e.severity) {
                Some(i) => {
                    pool.swap_remove(i);
                    *found.entry(e.severity).or_default() += 1;
                }
                None => missed.push(format!("{file}:{}: {} {}", e.line, e.severity, e.message)),
            }
        }
    }
    for severity in ["error", "warning", "info"] {
        eprintln!("{severity}: {} of {} expected messages found", found.get(severity).unwrap_or(&0), total.get(severity).unwrap_or(&0));
    }
    eprintln!("missed:\n{}", missed.join("\n"));
    let errors = total.get("error").copied().unwrap_or(0);
    assert!(errors > 150, "only {errors} expected errors read: is the data file complete?");
    let ratio = found.get("error").copied().unwrap_or(0) as f64 / errors as f64;
    // measured 175 of 178 (98.3 %) when this test was written; the issue asks for 90 %
    assert!(ratio >= 0.95, "{:.1} % of the expected error messages found; missed:\n{}", ratio * 100.0, missed.join("\n"));
    let warnings = total.get("warning").copied().unwrap_or(0);
    assert!(found.get("warning").copied().unwrap_or(0) * 10 >= warnings * 9, "deprecation and injection warnings: missed\n{}", missed.join("\n"));
}

#[test]
fn files_the_api_reads_without_error_give_no_error() {
    let Some(shared) = testkit::shared_dir() else { return };
    let suite = shared.join("checker-suite");
    for file in checker_suite_valid::VALID {
        let errors: Vec<String> = check_json(&suite.join(file), &[])
            .iter()
            .filter(|f| f["severity"] == "error")
            .filter(|f| !checker_suite_valid::beyond_the_schema(file, f["message"].as_str().unwrap_or("")))
            .map(|f| format!("{}:{}: {}", f["file"], f["line"], f["message"]))
            .collect();
        assert!(errors.is_empty(), "{file}:\n{}", errors.join("\n"));
    }
}

//! `osc2cr check` finds no error in any valid input we have: every scenario, parameter
//! distribution and catalog (each catalog read alone) of `../shared/corpus`, anything under
//! `../shared/tools`, the files of `../shared/checker-suite` that the ASAM OpenSCENARIO API reads
//! without error, and the project's `examples/`. A failure names each file with its errors.

use crate::common::*;

use std::collections::BTreeMap;
use std::path::PathBuf;

fn inputs() -> Vec<PathBuf> {
    let mut files = testkit::files_with_ext(&testkit::workspace_root().join("examples"), "xosc");
    if let Some(shared) = testkit::shared_dir() {
        files.extend(testkit::files_with_ext(&shared.join("corpus"), "xosc"));
        files.extend(testkit::files_with_ext(&shared.join("tools"), "xosc"));
        files.extend(checker_suite_valid::VALID.iter().map(|f| shared.join("checker-suite").join(f)));
    }
    files
}

#[test]
fn no_valid_input_has_an_error() {
    let files = inputs();
    let mut args = vec!["check".to_string(), "--json".to_string()];
    args.extend(files.iter().map(|f| f.display().to_string()));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let r = osc2cr(&args);
    let stderr = String::from_utf8_lossy(&r.stderr);
    let json: serde_json::Value = serde_json::from_slice(&r.stdout).unwrap_or_else(|e| panic!("{e}: {stderr}"));
    let mut errors: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for f in json.as_array().expect("an array") {
        let (file, message) = (f["file"].as_str().unwrap_or_default(), f["message"].as_str().unwrap_or_default());
        let name = file.rsplit('/').next().unwrap_or(file);
        // two ALKS files of the checker suite name a lane by a parameter's name: a lane that
        // cannot exist, which the API's schema reading does not look at (checker_suite.rs)
        // and what a file names but was not shipped with it (convert refuses it too)
        let beyond =
            if file.contains("checker-suite") { checker_suite_valid::beyond_the_schema(name, message) } else { checker_suite_valid::not_shipped(message) };
        if f["severity"] != "error" || beyond {
            continue;
        }
        errors.entry(file.to_string()).or_default().push(format!("{}:{}: {message}", f["line"], f["column"]));
    }
    let listed: Vec<String> = errors.iter().map(|(file, es)| format!("{file}:\n  {}", es.join("\n  "))).collect();
    assert!(errors.is_empty(), "{} of {} files have errors:\n{}", errors.len(), files.len(), listed.join("\n"));
    // every file was read (none skipped as a catalog of a folder, none missing): the text
    // output's count says so
    let text_args: Vec<&str> = args.iter().copied().filter(|a| *a != "--json").collect();
    let counted = String::from_utf8_lossy(&osc2cr(&text_args).stderr).to_string();
    let checked = format!("{} file{} checked", files.len(), if files.len() == 1 { "" } else { "s" });
    assert!(counted.contains(&checked), "expected {checked:?} in {counted}");
    if testkit::shared_dir().is_some() {
        assert!(files.len() > 200, "only {} inputs found", files.len());
    }
}

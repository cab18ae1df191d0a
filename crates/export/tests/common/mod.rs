//! What the feature modules share: the CommonRoad scenarios the acceptance criteria name (the
//! corpus converted by `convert` into `target/`, once per run, and `../shared/commonroad-scenarios`),
//! fresh output folders under `target/`, exporting a file, and esmini.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// A fresh folder `target/export-tests/<name>`.
pub fn fresh_dir(name: &str) -> PathBuf {
    let d = testkit::workspace_root().join("target/export-tests").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("create the test folder");
    d
}

static CORPUS: OnceLock<Vec<PathBuf>> = OnceLock::new();

/// Every CommonRoad file of the corpus conversions: `../shared/corpus` converted (2020a) by the
/// `convert` crate into `target/export-tests/corpus-commonroad`, once per test run. Empty when
/// the shared folder is absent (testkit prints the notice; under CI it fails).
pub fn corpus_commonroad() -> &'static [PathBuf] {
    CORPUS.get_or_init(|| {
        let Some(shared) = testkit::shared_dir() else { return Vec::new() };
        let out = fresh_dir("corpus-commonroad");
        let batch = convert::BatchOptions {
            out_dir: out.clone(),
            jobs: 2,
            timeout: Some(std::time::Duration::from_secs(120)),
            shard: None,
            render: false,
            resume: false,
        };
        let report = convert::run_batch(&[shared.join("corpus")], &convert::ConvertOptions::default(), &batch, &convert::Silent).expect("the corpus converts");
        assert!(report.scenarios.len() > 300, "the corpus conversion made {} scenarios", report.scenarios.len());
        testkit::files_with_ext(&out, "xml")
    })
}

/// Every scenario of `../shared/commonroad-scenarios` (empty when absent).
pub fn commonroad_scenarios() -> Vec<PathBuf> {
    testkit::shared_dir().map(|s| testkit::files_with_ext(&s.join("commonroad-scenarios"), "xml")).unwrap_or_default()
}

/// The files both acceptance sets hold: the corpus conversions and the CommonRoad scenarios.
pub fn all_scenarios() -> Vec<PathBuf> {
    let mut v = commonroad_scenarios();
    v.extend(corpus_commonroad().iter().cloned());
    v
}

/// The scenario's path shown in messages: relative to the shared folder or `target/`.
pub fn short(p: &Path) -> String {
    let s = p.display().to_string();
    match s.find("commonroad-scenarios/").or_else(|| s.find("corpus-commonroad/")) {
        Some(i) => s[i..].to_string(),
        None => s,
    }
}

/// Exports `input` into `dir` as the CLI does (the `.xosc` named after the input, the map
/// beside it); returns the `.xosc` path and the export.
pub fn export_into(input: &Path, dir: &Path, options: &export::ExportOptions) -> Result<(PathBuf, export::Exported), String> {
    let source = export::read_source(input)?;
    let exported = export::export(&source, "", options).map_err(|e| e.to_string())?;
    let xosc = dir.join(format!("{}.xosc", export::scenario_name(input)));
    std::fs::write(&xosc, &exported.xosc).map_err(|e| e.to_string())?;
    if let Some(m) = &exported.map {
        std::fs::write(dir.join(&m.file_name), &m.xodr).map_err(|e| e.to_string())?;
    }
    Ok((xosc, exported))
}

/// esmini 3.6.0 of the shared tools, if it runs here.
pub fn esmini() -> Option<PathBuf> {
    let shared = testkit::shared_dir()?;
    let bin = shared.join("tools/esmini/bin/esmini-3.6.0");
    let runs = std::process::Command::new(&bin).arg("--version").output().is_ok_and(|o| o.status.success() || !o.stdout.is_empty());
    if runs {
        return Some(bin);
    }
    if std::env::var_os("CI").is_some() {
        panic!("esmini {} does not run here (CI is set, so tests that need it fail)", bin.display());
    }
    eprintln!("notice: esmini {} does not run here; skipping this test", bin.display());
    None
}

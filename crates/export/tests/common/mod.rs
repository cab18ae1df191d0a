//! What the feature modules share: the CommonRoad scenarios the acceptance criteria name (the
//! corpus converted by `convert` into `target/`, once per run, and `../shared/commonroad-scenarios`),
//! fresh output folders under `target/`, exporting them as one batch, and esmini.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// A fresh folder `target/export-tests/<name>`.
pub(crate) fn fresh_dir(name: &str) -> PathBuf {
    let d = testkit::workspace_root().join("target/export-tests").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("create the test folder");
    d
}

static CORPUS: OnceLock<Vec<PathBuf>> = OnceLock::new();

/// Every CommonRoad file of the corpus conversions: `../shared/corpus` converted (2020a) by the
/// `convert` crate into `target/export-tests/corpus-commonroad`, once per test run. Empty when
/// the shared folder is absent (testkit prints the notice; under CI it fails).
pub(crate) fn corpus_commonroad() -> &'static [PathBuf] {
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
pub(crate) fn commonroad_scenarios() -> Vec<PathBuf> {
    testkit::shared_dir().map(|s| testkit::files_with_ext(&s.join("commonroad-scenarios"), "xml")).unwrap_or_default()
}

/// The files both acceptance sets hold: the CommonRoad scenarios and the corpus conversions —
/// all of them with `OSC2CR_EXPORT_FULL=1`, else (the default, and CI's) the first two
/// variations of each parameter distribution (`NAME_1`, `NAME_2`: the other variations differ
/// only in parameter values), which halves the set. A notice says which.
pub(crate) fn acceptance_scenarios() -> Vec<PathBuf> {
    let mut v = commonroad_scenarios();
    let corpus = corpus_commonroad();
    let full = std::env::var_os("OSC2CR_EXPORT_FULL").is_some_and(|x| x == "1");
    let later_variation = |p: &PathBuf| {
        let stem = p.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        let Some((base, k)) = stem.rsplit_once('_') else { return false };
        let first = p.with_file_name(format!("{base}_1.xml"));
        k.parse::<u64>().is_ok_and(|k| k > 2) && corpus.contains(&first)
    };
    let kept: Vec<PathBuf> = corpus.iter().filter(|p| full || !later_variation(p)).cloned().collect();
    if !full && !corpus.is_empty() {
        eprintln!(
            "notice: {} of the {} corpus conversions (the first two variations of each distribution); OSC2CR_EXPORT_FULL=1 runs all",
            kept.len(),
            corpus.len()
        );
    }
    v.extend(kept);
    v
}

/// Exports `inputs` as one batch into `out` (maps shared, names made unique); returns each
/// input with its `.xosc`, or why it was not exported.
pub(crate) fn export_batch(inputs: &[PathBuf], out: &Path, options: &export::ExportOptions) -> Vec<(PathBuf, Result<PathBuf, String>)> {
    let batch = export::BatchOptions { out_dir: out.to_path_buf(), jobs: 2, export: options.clone() };
    let totals = export::run_batch(inputs, &batch, &mut |_| {}).expect("the batch runs");
    totals
        .reports
        .into_iter()
        .map(|r| {
            let result = match (r.output, r.failure) {
                (Some(x), None) => Ok(x),
                (_, f) => Err(f.map_or_else(|| "not exported".to_string(), |f| f.message)),
            };
            (r.input, result)
        })
        .collect()
}

/// The scenario's path shown in messages: relative to the shared folder or `target/`.
pub(crate) fn short(p: &Path) -> String {
    let s = p.display().to_string();
    match s.find("commonroad-scenarios/").or_else(|| s.find("corpus-commonroad/")) {
        Some(i) => s[i..].to_string(),
        None => s,
    }
}

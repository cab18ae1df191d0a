//! A batch: the inputs (files as given, folders searched for `.xml` and `*-SC.pb` files,
//! sorted: `batch_inputs`), exported by `jobs` threads, reports handed on in input order. Each scenario's
//! `.xosc` is written whole or not at all (`commonroad::xml::write_atomic`), at the input's
//! place under the output folder (`<sub-folder>/<name>.xosc`; a name already taken gets `-2`,
//! `-3`, …); the maps go to the top of the output folder, each written once, and a file of that
//! name with other bytes is an error, never overwritten. A scenario that fails does not stop
//! the batch.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::time::Instant;

use batch_inputs::MAX_FILES;

use crate::map_file::{MapCache, MapFile};
use crate::options::ExportOptions;
use crate::report::{summarise, BatchTotals, Failure, MapReport, Report, Skipped, Stage, Status};
use crate::source::{is_input, read_source, scenario_name};

/// A batch's settings.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchOptions {
    pub out_dir: PathBuf,
    /// Scenarios exported at once (at least 1).
    pub jobs: usize,
    pub export: ExportOptions,
}

/// A scenario file of the batch.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Found {
    pub path: PathBuf,
    /// The summary's group.
    pub folder: String,
    /// The output path under the output folder, without `.xosc`.
    pub output_stem: PathBuf,
}

/// A CommonRoad XML file names `<commonRoad` near its start; other XML files of a folder are
/// passed over.
fn commonroad_xml(path: &Path) -> bool {
    use std::io::Read;
    let mut head = vec![0u8; 4096];
    let n = std::fs::File::open(path).and_then(|mut f| f.read(&mut head)).unwrap_or(0);
    String::from_utf8_lossy(&head[..n]).contains("<commonRoad")
}

/// The scenario files of `inputs` in argument order (each folder's sorted), and the files of
/// folders passed over.
pub fn discover(inputs: &[PathBuf]) -> Result<(Vec<Found>, Vec<Skipped>), String> {
    let mut found = Vec::new();
    let mut skipped = Vec::new();
    for input in inputs {
        // other XML files of a folder are passed over; a file named is read, and its reader says
        // what is wrong with it
        let searched = input.is_dir();
        for g in batch_inputs::files_of(input, &is_input, "scenario files")? {
            if searched && g.path.extension().is_some_and(|e| e.eq_ignore_ascii_case("xml")) && !commonroad_xml(&g.path) {
                skipped.push(Skipped { path: g.path, reason: "not a CommonRoad file (no <commonRoad> root)".into() });
                continue;
            }
            found.push(Found { output_stem: g.sub.join(scenario_name(&g.path)), path: g.path, folder: g.folder });
        }
        if found.len() > MAX_FILES {
            return Err(format!("more than {MAX_FILES} files to export"));
        }
    }
    // a name already taken gets -2, -3, …
    let mut taken = BTreeSet::new();
    for f in &mut found {
        let mut stem = f.output_stem.clone();
        let mut k = 2;
        while !taken.insert(stem.clone()) {
            let mut name = f.output_stem.file_name().unwrap_or_default().to_os_string();
            name.push(format!("-{k}"));
            stem = f.output_stem.with_file_name(name);
            k += 1;
        }
        f.output_stem = stem;
    }
    Ok((found, skipped))
}

/// Maps written by this batch (file name → bytes written), so each is written once.
type Written = Mutex<HashMap<String, Arc<MapFile>>>;

fn write_map(out_dir: &Path, map: &Arc<MapFile>, written: &Written) -> Result<(), String> {
    let mut w = written.lock().map_err(|_| "a writer thread failed".to_string())?;
    if w.contains_key(&map.file_name) {
        return Ok(());
    }
    let path = out_dir.join(&map.file_name);
    match std::fs::read(&path) {
        Ok(bytes) if bytes == map.xodr.as_bytes() => {}
        Ok(_) => return Err(format!("{} exists with other content; a map of that name is not overwritten", path.display())),
        Err(_) => commonroad::xml::write_atomic(&path, map.xodr.as_bytes()).map_err(|e| e.to_string())?,
    }
    w.insert(map.file_name.clone(), map.clone());
    Ok(())
}

fn fail(stage: Stage, message: String) -> Failure {
    Failure { stage, message }
}

fn one(found: &Found, options: &BatchOptions, cache: &MapCache, written: &Written) -> Report {
    let start = Instant::now();
    let mut report = Report {
        input: found.path.clone(),
        folder: found.folder.clone(),
        status: Status::Failed,
        output: None,
        map: None,
        failure: None,
        warnings: Vec::new(),
        facts: None,
        time_ms: 0.0,
    };
    let result = (|| -> Result<(), Failure> {
        let source = read_source(&found.path).map_err(|e| fail(Stage::Read, e))?;
        let depth = found.output_stem.parent().map_or(0, |p| p.components().count());
        let prefix = "../".repeat(depth);
        let map = cache.get(&source.scenario).map_err(|e| fail(Stage::Map, e))?;
        let exported = crate::exported::export_with(&source, &prefix, &options.export, cache).map_err(|e| fail(Stage::Scenario, e.0))?;
        report.warnings = exported.warnings;
        report.facts = Some(exported.facts);
        let out = options.out_dir.join(&found.output_stem).with_extension("xosc");
        if let Some(parent) = out.parent() {
            std::fs::create_dir_all(parent).map_err(|e| fail(Stage::Write, format!("cannot create {}: {e}", parent.display())))?;
        }
        if let Some(m) = &map {
            write_map(&options.out_dir, m, written).map_err(|e| fail(Stage::Write, e))?;
            report.map = Some(m.file_name.clone());
        }
        commonroad::xml::write_atomic(&out, exported.xosc.as_bytes()).map_err(|e| fail(Stage::Write, e.to_string()))?;
        report.output = Some(out);
        Ok(())
    })();
    match result {
        Ok(()) => report.status = Status::Exported,
        Err(f) => report.failure = Some(f),
    }
    report.time_ms = start.elapsed().as_secs_f64() * 1e3;
    report
}

/// Exports one scenario file into `out_dir` as a batch of it alone does: `<name>.xosc` there,
/// its map beside it. The report says what was written, or why not.
pub fn export_file(input: &Path, out_dir: &Path, options: &ExportOptions) -> Report {
    let found = Found { path: input.to_path_buf(), folder: batch_inputs::label(out_dir), output_stem: PathBuf::from(scenario_name(input)) };
    let batch = BatchOptions { out_dir: out_dir.to_path_buf(), jobs: 1, export: options.clone() };
    // `one` makes the output folder (the `.xosc`'s folder) before it writes the map into it
    one(&found, &batch, &MapCache::new(), &Mutex::new(HashMap::new()))
}

/// Exports every scenario of `inputs`; `sink` gets each report in input order as it is ready.
pub fn run_batch(inputs: &[PathBuf], options: &BatchOptions, sink: &mut dyn FnMut(&Report)) -> Result<BatchTotals, String> {
    let (found, skipped) = discover(inputs)?;
    std::fs::create_dir_all(&options.out_dir).map_err(|e| format!("cannot create {}: {e}", options.out_dir.display()))?;
    let cache = MapCache::new();
    let written: Written = Mutex::new(HashMap::new());
    let next = AtomicUsize::new(0);
    let (tx, rx) = mpsc::channel::<(usize, Report)>();
    let mut reports: Vec<Report> = Vec::with_capacity(found.len());
    std::thread::scope(|scope| {
        for _ in 0..options.jobs.clamp(1, found.len().max(1)) {
            let tx = tx.clone();
            let (found, cache, written, next) = (&found, &cache, &written, &next);
            scope.spawn(move || loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(f) = found.get(i) else { break };
                if tx.send((i, one(f, options, cache, written))).is_err() {
                    break;
                }
            });
        }
        drop(tx);
        // hand reports on in input order
        let mut waiting: BTreeMap<usize, Report> = BTreeMap::new();
        for (i, r) in rx {
            waiting.insert(i, r);
            while let Some(r) = waiting.remove(&reports.len()) {
                sink(&r);
                reports.push(r);
            }
        }
    });
    let exported = reports.iter().filter(|r| r.status == Status::Exported).count();
    let mut maps: BTreeMap<String, MapReport> = BTreeMap::new();
    if let Ok(w) = written.lock() {
        for (name, m) in w.iter() {
            maps.insert(name.clone(), MapReport { file: name.clone(), scenarios: 0, warnings: m.warnings.clone() });
        }
    }
    for r in &reports {
        if let Some(m) = r.map.as_ref().and_then(|m| maps.get_mut(m)) {
            m.scenarios += 1;
        }
    }
    let maps: Vec<MapReport> = maps.into_values().collect();
    Ok(BatchTotals {
        exported,
        failed: reports.len() - exported,
        warnings: reports.iter().map(|r| r.warnings.len()).sum::<usize>() + maps.iter().map(|m| m.warnings.len()).sum::<usize>(),
        skipped,
        summary: summarise(&reports),
        maps,
        reports,
    })
}

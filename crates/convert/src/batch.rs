//! A batch: every scenario (and every parameter variation) of the inputs, converted on `jobs`
//! worker threads, each within a time limit, each output written whole or not at all. A
//! failing scenario never stops the others.
//!
//! It streams: the work is handed out one conversion at a time ([`crate::plan`]), at most a
//! bounded number of reports wait for a slower one before them, and each report goes to the
//! caller's sink in batch order as soon as it can — so a sweep of 100,000 variations runs in
//! flat memory, whatever the number of threads, and its reports come out in the same order.
//! The conversions share one [`Caches`] (each OpenDRIVE file read and converted once, each 2024
//! map encoded and written once). With a shard, every output is still named on the whole batch,
//! and only the shard's part is converted; with `resume`, a conversion whose files an earlier
//! run wrote is not converted again, and the temporary files of killed writers are removed.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::time::Duration;

use crate::cache::Caches;
use crate::discover::discover;
use crate::options::ConvertOptions;
use crate::outputs::{complete, write_output, MapFiles, OutputPaths, Written};
use crate::picture::write_picture;
use crate::pipeline::{convert, Conversion, Model, Request};
use crate::plan::{Job, Plan, Work};
use crate::report::{BatchReport, Failure, FolderSummary, ScenarioReport, Skipped, Stage, StageWarning, Status, Timings, Variation};
use crate::shard::Shard;
use crate::single::batch_source;
use crate::summary::Summary;

/// How a batch runs.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchOptions {
    pub out_dir: PathBuf,
    /// Worker threads (at least 1).
    pub jobs: usize,
    /// Wall-clock limit per scenario; `None`: none.
    pub timeout: Option<Duration>,
    /// Convert only this part of the batch (`None`: all of it).
    pub shard: Option<Shard>,
    /// Also write a PNG picture beside every converted scenario (`--render`).
    pub render: bool,
    /// Leave out a conversion whose output files are all there from an earlier run of the same
    /// batch (it is reported `complete`), and remove the temporary files a killed run left.
    pub resume: bool,
}

/// Told about the batch's progress (e.g. a progress bar).
pub trait Progress: Sync {
    /// The number of conversions the batch will run.
    fn start(&self, _total: usize) {}
    /// One conversion finished.
    fn done(&self, _report: &ScenarioReport) {}
}

/// No progress reporting.
pub struct Silent;
impl Progress for Silent {}

/// What a batch did besides the reports it handed to its sink.
#[derive(Debug, Clone, PartialEq)]
pub struct BatchSummary {
    pub skipped: Vec<Skipped>,
    /// The summary table's rows.
    pub summary: Vec<FolderSummary>,
    /// Conversions of the whole batch, all shards together.
    pub planned: usize,
    pub converted: usize,
    pub failed: usize,
    /// Found complete from an earlier run (`resume`).
    pub complete: usize,
    /// Warnings of all reports.
    pub warnings: usize,
    /// Some conversion failed while reading its input (load or road network stage).
    pub input_failed: bool,
    /// Temporary files of killed writers removed before the batch (`resume`).
    pub removed_temporaries: Vec<PathBuf>,
}

/// Reports waiting for an earlier, slower conversion, per worker, before workers pause.
const WAITING_PER_WORKER: usize = 256;

/// Finds, converts and writes everything `inputs` name, and hands each conversion's report to
/// `sink` with its position in the batch, in batch order. `Err` only for a bad argument (a path
/// that does not exist, an invalid option, an output folder that cannot be created).
pub fn run_batch_streaming(
    inputs: &[PathBuf],
    options: &ConvertOptions,
    batch: &BatchOptions,
    progress: &dyn Progress,
    sink: &mut dyn FnMut(usize, ScenarioReport),
) -> Result<BatchSummary, String> {
    options.check()?;
    // the inputs first: a batch whose input does not exist leaves no output folder behind
    let found = discover(inputs)?;
    std::fs::create_dir_all(&batch.out_dir).map_err(|e| format!("cannot create output folder {}: {e}", batch.out_dir.display()))?;
    let removed_temporaries = if batch.resume { commonroad::xml::remove_stale_temporaries(&batch.out_dir) } else { Vec::new() };
    let plan = Plan::new(found, options);
    let planned = plan.planned;
    let mut skipped = plan.skipped.clone();
    // skipped files are reported once, by the first shard, so that the shards' reports together
    // list what one unsharded report lists
    if batch.shard.is_some_and(|s| s.index() != 1) {
        skipped.clear();
    }
    progress.start(plan.in_shard(batch.shard));

    let jobs = batch.jobs.max(1);
    let shared = Shared {
        options: Arc::new(options.clone()),
        caches: Arc::new(Caches::with_capacity((2 * jobs).max(4))),
        maps: MapFiles::new(&batch.out_dir),
        batch: batch.clone(),
    };
    let work = Mutex::new(plan.work(&batch.out_dir, options.format, batch.shard).enumerate());
    let emitted = AtomicUsize::new(0);
    let issued = AtomicUsize::new(0);
    let window = WAITING_PER_WORKER * jobs;
    let mut summary = Summary::default();
    let mut totals =
        BatchSummary { skipped, summary: Vec::new(), planned, converted: 0, failed: 0, complete: 0, warnings: 0, input_failed: false, removed_temporaries };
    std::thread::scope(|scope| -> Result<(), String> {
        let (tx, rx) = mpsc::sync_channel::<(usize, usize, ScenarioReport)>(2 * jobs);
        for _ in 0..jobs {
            let tx = tx.clone();
            let (work, shared, emitted, issued) = (&work, &shared, &emitted, &issued);
            std::thread::Builder::new()
                .spawn_scoped(scope, move || loop {
                    // pause while too many reports wait for a slower conversion before them
                    while issued.load(Ordering::Acquire) >= emitted.load(Ordering::Acquire) + window {
                        std::thread::sleep(Duration::from_millis(2));
                    }
                    let next = match work.lock() {
                        Ok(mut w) => w.next(),
                        Err(poisoned) => poisoned.into_inner().next(),
                    };
                    let Some((seq, (position, work))) = next else { break };
                    issued.fetch_add(1, Ordering::AcqRel);
                    let report = match work {
                        Work::Convert(job) => run_job(&job, shared),
                        Work::Failed(report) => *report,
                    };
                    if tx.send((seq, position, report)).is_err() {
                        break;
                    }
                })
                .map_err(|e| format!("cannot start {jobs} worker threads: {e}"))?;
        }
        drop(tx);
        let mut waiting: BTreeMap<usize, (usize, ScenarioReport)> = BTreeMap::new();
        let mut next = 0usize;
        for (seq, position, report) in rx {
            progress.done(&report);
            waiting.insert(seq, (position, report));
            while let Some((position, report)) = waiting.remove(&next) {
                summary.add(&report);
                totals.warnings += report.warnings.len();
                match report.status {
                    Status::Converted => totals.converted += 1,
                    Status::Complete => totals.complete += 1,
                    Status::Failed => {
                        totals.failed += 1;
                        totals.input_failed |= report.failure.as_ref().is_some_and(|f| matches!(f.stage, Stage::Load | Stage::RoadNetwork));
                    }
                }
                sink(position, report);
                next += 1;
                emitted.store(next, Ordering::Release);
            }
        }
        Ok(())
    })?;
    totals.summary = summary.rows();
    Ok(totals)
}

/// Like [`run_batch_streaming`], collecting every report (for batches small enough to list).
pub fn run_batch(inputs: &[PathBuf], options: &ConvertOptions, batch: &BatchOptions, progress: &dyn Progress) -> Result<BatchReport, String> {
    let mut scenarios = Vec::new();
    let totals = run_batch_streaming(inputs, options, batch, progress, &mut |_, r| scenarios.push(r))?;
    Ok(BatchReport { scenarios, skipped: totals.skipped, summary: totals.summary, planned: totals.planned })
}

/// What every worker reads.
struct Shared {
    options: Arc<ConvertOptions>,
    caches: Arc<Caches>,
    maps: MapFiles,
    batch: BatchOptions,
}

/// Converts in a worker thread so that a scenario over its time limit can be abandoned: the
/// engine gets the limit as its deadline and stops itself; loading and map conversion cannot
/// be interrupted, so a thread stuck there finishes on its own and its result is discarded.
fn convert_limited(job: &Job, parameters: Vec<(String, String)>, shared: &Shared, keep: bool) -> (Conversion, Option<Model>) {
    let config = job.variation.as_ref().map_or(1, |(k, _)| *k);
    let source = batch_source(&job.input, job.variation.as_ref().map(|(k, _)| *k));
    let Some(limit) = shared.batch.timeout else {
        let request =
            Request { config, parameters: &parameters, source, keep_model: keep, ..Request::named(&job.scenario, &job.name).with_caches(&shared.caches) };
        return convert(&request, &shared.options);
    };
    let (tx, rx) = mpsc::channel();
    let (path, name) = (job.scenario.clone(), job.name.clone());
    let opts = Arc::new(ConvertOptions { deadline: Some(std::time::Instant::now() + limit), ..ConvertOptions::clone(&shared.options) });
    let caches = shared.caches.clone();
    let spawned = std::thread::Builder::new().spawn(move || {
        let request = Request { config, parameters: &parameters, source, keep_model: keep, ..Request::named(&path, &name).with_caches(&caches) };
        let _ = tx.send(convert(&request, &opts));
    });
    let timed_out = |msg: String| Conversion {
        result: Err(Failure { stage: Stage::Timeout, message: msg }),
        warnings: Vec::new(),
        timings: Timings { total_ms: limit.as_secs_f64() * 1e3, ..Timings::default() },
        facts: Default::default(),
    };
    if let Err(e) = spawned {
        return (timed_out(format!("cannot start a worker thread: {e}")), None);
    }
    match rx.recv_timeout(limit) {
        Ok(c) => c,
        Err(_) => {
            let message = format!("not converted within the time limit of {} s (--timeout)", limit.as_secs_f64());
            (timed_out(message), None)
        }
    }
}

fn report(job: &Job, variation: Option<Variation>, status: Status) -> ScenarioReport {
    ScenarioReport::new(job.input.clone(), job.folder.clone(), variation, status)
}

fn run_job(job: &Job, shared: &Shared) -> ScenarioReport {
    let batch = &shared.batch;
    let parameters = match &job.variation {
        Some((k, dist)) => k.checked_sub(1).and_then(|i| dist.get(i)).unwrap_or_default(),
        None => Vec::new(),
    };
    let variation = job.variation.as_ref().map(|(k, dist)| Variation { index: *k, scenario_file: dist.scenario_file.clone(), parameters: parameters.clone() });
    let paths = OutputPaths::of(&job.stem, shared.options.format, batch.render);
    if batch.resume {
        if let Some(written) = complete(&paths, &batch.out_dir) {
            let mut r = report(job, variation, Status::Complete);
            (r.output, r.dynamic, r.map) = (written.main, written.dynamic, written.map);
            r.picture = paths.picture;
            return r;
        }
    }
    let (mut c, model) = convert_limited(job, parameters, shared, batch.render);
    let mut warnings = job.notes.to_vec();
    warnings.append(&mut c.warnings);
    let mut written = Written::default();
    let failure = match &c.result {
        Ok(output) => {
            let t = std::time::Instant::now();
            let result = write_output(&paths, output, &shared.maps);
            let dt = t.elapsed().as_secs_f64() * 1e3;
            c.timings.write_ms += dt;
            c.timings.total_ms += dt;
            match result {
                Ok(w) => {
                    written = w;
                    None
                }
                Err(message) => Some(Failure { stage: Stage::Write, message }),
            }
        }
        Err(f) => Some(f.clone()),
    };
    // a picture that cannot be drawn or written is a warning: the scenario itself is fine
    let mut picture = None;
    if let (Some(_), Some(model)) = (&written.main, &model) {
        let beside: &Path = written.dynamic.as_deref().unwrap_or(&paths.main);
        match write_picture(beside, model) {
            Ok(p) => picture = Some(p),
            Err(message) => warnings.push(StageWarning { stage: Stage::Render, message }),
        }
    }
    let mut r = report(job, variation, if failure.is_none() { Status::Converted } else { Status::Failed });
    (r.output, r.dynamic, r.map) = (written.main, written.dynamic, written.map);
    r.failure = failure;
    r.warnings = warnings;
    r.timings = c.timings;
    r.facts = c.facts;
    r.picture = picture;
    r
}

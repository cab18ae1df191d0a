//! A batch: every scenario (and every parameter variation) of the inputs, converted in
//! parallel on `jobs` threads, each within a time limit, each output written whole or not at
//! all. Results come back in input order whatever the number of threads, and a failing
//! scenario never stops the others. With a shard, every output is still named on the whole
//! batch, and only the shard's part is converted.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::{mpsc, Arc};
use std::time::Duration;

use openscenario::{Content, LoadOptions};
use rayon::prelude::*;

use crate::discover::{discover, FileKind, Found};
use crate::options::ConvertOptions;
use crate::picture::write_picture;
use crate::pipeline::{convert_scenario_keeping, Conversion, Model, Request};
use crate::report::{
    BatchReport, Failure, ScenarioReport, Skipped, Stage, StageWarning, Status, Timings, Variation,
};
use crate::shard::Shard;
use crate::single::{batch_name, batch_source};
use crate::summary::summarise;

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
}

/// Told about the batch's progress (e.g. a progress bar); called from worker threads.
pub trait Progress: Sync {
    /// The number of conversions the batch will run.
    fn start(&self, _total: usize) {}
    /// One conversion finished.
    fn done(&self, _report: &ScenarioReport) {}
}

/// No progress reporting.
pub struct Silent;
impl Progress for Silent {}

/// One conversion to run.
#[derive(Debug, Clone)]
struct Job {
    input: PathBuf,
    folder: String,
    scenario: PathBuf,
    name: String,
    output: PathBuf,
    variation: Option<Variation>,
    /// Warnings known before the run (e.g. a capped distribution).
    notes: Vec<StageWarning>,
}

/// Finds, converts and writes everything `inputs` name. `Err` only for a bad argument (a path
/// that does not exist, an invalid option, an output folder that cannot be created).
pub fn run_batch(
    inputs: &[PathBuf],
    options: &ConvertOptions,
    batch: &BatchOptions,
    progress: &dyn Progress,
) -> Result<BatchReport, String> {
    options.check()?;
    std::fs::create_dir_all(&batch.out_dir)
        .map_err(|e| format!("cannot create output folder {}: {e}", batch.out_dir.display()))?;
    let found = discover(inputs)?;
    let mut skipped = Vec::new();
    let mut early = Vec::new(); // (position, report) of distributions that failed to load
    let mut jobs = plan(&found, options, &batch.out_dir, &mut skipped, &mut early);
    let planned = jobs.len() + early.len();
    if let Some(shard) = batch.shard {
        jobs.retain(|(pos, _)| shard.contains(*pos));
        early.retain(|(pos, _)| shard.contains(*pos));
        // skipped files are reported once, by the first shard, so that the shards' reports
        // together list what one unsharded report lists
        if shard.index() != 1 {
            skipped.clear();
        }
    }
    progress.start(jobs.len() + early.len());
    for (_, r) in &early {
        progress.done(r);
    }

    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(batch.jobs.max(1))
        .build()
        .map_err(|e| format!("cannot start {} worker threads: {e}", batch.jobs))?;
    let options = Arc::new(options.clone());
    let run: Vec<(usize, ScenarioReport)> = pool.install(|| {
        jobs.par_iter()
            .map(|(pos, job)| {
                let report = run_job(job, &options, batch.timeout, batch.render);
                progress.done(&report);
                (*pos, report)
            })
            .collect()
    });
    let mut all: Vec<(usize, ScenarioReport)> = early.into_iter().chain(run).collect();
    all.sort_by_key(|(pos, _)| *pos);
    let scenarios: Vec<ScenarioReport> = all.into_iter().map(|(_, r)| r).collect();
    let summary = summarise(&scenarios);
    Ok(BatchReport {
        scenarios,
        skipped,
        summary,
        planned,
    })
}

/// Expands distributions into variations and names every output (unique, in input order).
fn plan(
    found: &[Found],
    options: &ConvertOptions,
    out_dir: &Path,
    skipped: &mut Vec<Skipped>,
    early: &mut Vec<(usize, ScenarioReport)>,
) -> Vec<(usize, Job)> {
    let mut used = BTreeSet::new();
    let mut jobs = Vec::new();
    let mut pos = 0usize;
    for f in found {
        match &f.kind {
            FileKind::Skip(reason) => skipped.push(Skipped {
                path: f.path.clone(),
                reason: reason.clone(),
            }),
            FileKind::Scenario => {
                let output = unique(out_dir, &f.output_stem, &mut used);
                jobs.push((
                    pos,
                    Job {
                        input: f.path.clone(),
                        folder: f.folder.clone(),
                        scenario: f.path.clone(),
                        name: batch_name(&f.path),
                        output,
                        variation: None,
                        notes: Vec::new(),
                    },
                ));
                pos += 1;
            }
            FileKind::Distribution => {
                let load = LoadOptions {
                    parameters: options.parameters.clone(),
                    seed: options.seed,
                    ..Default::default()
                };
                let (dist, problems) = match openscenario::load(&f.path, &load) {
                    Ok(l) if !l.problems.is_empty() && !options.lenient => {
                        let list: Vec<String> = l.problems.iter().map(ToString::to_string).collect();
                        let message = format!("the distribution cannot be sampled (--lenient samples it anyway):\n{}", list.join("\n"));
                        early.push((pos, failed_early(f, &message)));
                        pos += 1;
                        continue;
                    }
                    Ok(l) => match l.content {
                        Content::Distribution(d) => (d, l.problems),
                        _ => {
                            early.push((pos, failed_early(f, "expected a ParameterValueDistribution")));
                            pos += 1;
                            continue;
                        }
                    },
                    Err(e) => {
                        early.push((pos, failed_early(f, &e.to_string())));
                        pos += 1;
                        continue;
                    }
                };
                let total = dist.len();
                let n = total.min(options.max_variations);
                let mut notes: Vec<StageWarning> =
                    problems.iter().map(|p| StageWarning { stage: Stage::Load, message: p.to_string() }).collect();
                if total > n {
                    notes.push(StageWarning {
                        stage: Stage::Load,
                        message: format!(
                            "the distribution has {total} parameter sets; the first {n} are converted (--max-variations)"
                        ),
                    });
                }
                for (i, parameters) in dist.iter().take(usize::try_from(n).unwrap_or(usize::MAX)).enumerate() {
                    let k = i as u64 + 1;
                    let mut stem = f.output_stem.clone().into_os_string();
                    stem.push(format!("_{k}"));
                    let output = unique(out_dir, Path::new(&stem), &mut used);
                    jobs.push((
                        pos,
                        Job {
                            input: f.path.clone(),
                            folder: f.folder.clone(),
                            scenario: dist.scenario_file.clone(),
                            name: batch_name(&f.path),
                            output,
                            variation: Some(Variation {
                                index: k,
                                scenario_file: dist.scenario_file.clone(),
                                parameters,
                            }),
                            notes: notes.clone(),
                        },
                    ));
                    pos += 1;
                }
            }
        }
    }
    jobs
}

/// `out_dir/stem.xml`, or `stem-2.xml`, `stem-3.xml`, … when taken.
fn unique(out_dir: &Path, stem: &Path, used: &mut BTreeSet<PathBuf>) -> PathBuf {
    let mut n = 1u64;
    loop {
        let mut name = stem.as_os_str().to_owned();
        if n > 1 {
            name.push(format!("-{n}"));
        }
        name.push(".xml");
        let p = out_dir.join(name);
        if used.insert(p.clone()) {
            return p;
        }
        n += 1;
    }
}

fn failed_early(f: &Found, message: &str) -> ScenarioReport {
    ScenarioReport {
        input: f.path.clone(),
        folder: f.folder.clone(),
        output: None,
        variation: None,
        status: Status::Failed,
        failure: Some(Failure {
            stage: Stage::Load,
            message: message.to_string(),
        }),
        warnings: Vec::new(),
        timings: Timings::default(),
        benchmark_id: None,
        ego: None,
        lanelets: 0,
        obstacles: 0,
        duration_s: None,
        tags: Vec::new(),
        picture: None,
    }
}

/// Converts in a worker thread so that a scenario over its time limit can be abandoned: the
/// engine gets the limit as its deadline and stops itself; loading and map conversion cannot
/// be interrupted, so a thread stuck there finishes on its own and its result is discarded.
fn convert_limited(
    job: &Job,
    options: &Arc<ConvertOptions>,
    timeout: Option<Duration>,
    keep: bool,
) -> (Conversion, Option<Model>) {
    let source = batch_source(&job.input, job.variation.as_ref().map(|v| v.index));
    let params = job.variation.as_ref().map(|v| v.parameters.clone()).unwrap_or_default();
    let Some(limit) = timeout else {
        let request = Request {
            path: &job.scenario,
            name: &job.name,
            config: job.variation.as_ref().map_or(1, |v| v.index),
            parameters: &params,
            source,
        };
        return convert_scenario_keeping(&request, options, keep);
    };
    let (tx, rx) = mpsc::channel();
    let (path, name, config) = (
        job.scenario.clone(),
        job.name.clone(),
        job.variation.as_ref().map_or(1, |v| v.index),
    );
    let opts = Arc::new(ConvertOptions { deadline: Some(std::time::Instant::now() + limit), ..ConvertOptions::clone(options) });
    let spawned = std::thread::Builder::new().spawn(move || {
        let request = Request {
            path: &path,
            name: &name,
            config,
            parameters: &params,
            source,
        };
        let _ = tx.send(convert_scenario_keeping(&request, &opts, keep));
    });
    let timed_out = |msg: String| Conversion {
        result: Err(Failure {
            stage: Stage::Timeout,
            message: msg,
        }),
        warnings: Vec::new(),
        timings: Timings {
            total_ms: limit.as_secs_f64() * 1e3,
            ..Timings::default()
        },
        facts: Default::default(),
    };
    if let Err(e) = spawned {
        return (timed_out(format!("cannot start a worker thread: {e}")), None);
    }
    match rx.recv_timeout(limit) {
        Ok(c) => c,
        Err(_) => {
            let message = format!(
                "not converted within the time limit of {} s (--timeout)",
                limit.as_secs_f64()
            );
            (timed_out(message), None)
        }
    }
}

fn run_job(
    job: &Job,
    options: &Arc<ConvertOptions>,
    timeout: Option<Duration>,
    render: bool,
) -> ScenarioReport {
    let (mut c, model) = convert_limited(job, options, timeout, render);
    let mut warnings = job.notes.clone();
    warnings.append(&mut c.warnings);
    let mut output = None;
    let failure = match c.result {
        Ok(bytes) => {
            let t = std::time::Instant::now();
            let written = match job.output.parent() {
                Some(dir) => std::fs::create_dir_all(dir)
                    .map_err(|e| format!("cannot create folder {}: {e}", dir.display())),
                None => Ok(()),
            }
            .and_then(|()| {
                commonroad::xml::write_atomic(&job.output, &bytes).map_err(|e| e.to_string())
            });
            let dt = t.elapsed().as_secs_f64() * 1e3;
            c.timings.write_ms += dt;
            c.timings.total_ms += dt;
            match written {
                Ok(()) => {
                    output = Some(job.output.clone());
                    None
                }
                Err(message) => Some(Failure {
                    stage: Stage::Write,
                    message,
                }),
            }
        }
        Err(f) => Some(f),
    };
    // a picture that cannot be drawn or written is a warning: the scenario itself is fine
    let mut picture = None;
    if let (Some(out), Some(model)) = (&output, &model) {
        match write_picture(out, model) {
            Ok(p) => picture = Some(p),
            Err(message) => warnings.push(StageWarning {
                stage: Stage::Render,
                message,
            }),
        }
    }
    ScenarioReport {
        input: job.input.clone(),
        folder: job.folder.clone(),
        output,
        variation: job.variation.clone(),
        status: if failure.is_none() {
            Status::Converted
        } else {
            Status::Failed
        },
        failure,
        warnings,
        timings: c.timings,
        benchmark_id: c.facts.benchmark_id,
        ego: c.facts.ego,
        lanelets: c.facts.lanelets,
        obstacles: c.facts.obstacles,
        duration_s: c.facts.duration_s,
        tags: c.facts.tags,
        picture,
    }
}

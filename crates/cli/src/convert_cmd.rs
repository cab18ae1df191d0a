//! `osc2cr convert`: OpenSCENARIO files and folders in, one CommonRoad file per scenario (and
//! per parameter variation) out, with a summary table, an optional JSON report and a progress
//! bar on a terminal. All the work is `convert::run_batch`; this maps options and results.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Duration;

use convert::{BatchOptions, ConvertOptions, EgoChoice, GoalOptions, ScenarioReport, Stage, Status};

use crate::Failure;

#[derive(clap::Args)]
pub struct ConvertArgs {
    /// Scenario files (.xosc, parameter distributions included) and folders to search.
    #[arg(required = true, value_name = "FILE_OR_DIR")]
    pub inputs: Vec<PathBuf>,
    /// Output folder (created if missing); folders given as input keep their layout inside it.
    #[arg(short, long, value_name = "OUT_DIR")]
    pub output: PathBuf,
    /// CommonRoad time step, s.
    #[arg(long, default_value_t = 0.1)]
    pub dt: f64,
    /// Engine step, s.
    #[arg(long, default_value_t = 0.01)]
    pub step: f64,
    /// Simulated time after which a run stops, s.
    #[arg(long, default_value_t = 60.0)]
    pub max_time: f64,
    /// The ego entity, by exact name (default: first by name containing --ego-pattern).
    #[arg(long, value_name = "NAME")]
    pub ego: Option<String>,
    /// Text the ego's name contains (case-insensitive); else the first moving entity is the ego.
    #[arg(long, default_value = "ego", value_name = "TEXT")]
    pub ego_pattern: String,
    /// Leave the ego out of the obstacles (for motion-planning benchmarks).
    #[arg(long)]
    pub drop_ego: bool,
    /// Set a global parameter, NAME=VALUE (repeatable).
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = parse_param)]
    pub params: Vec<(String, String)>,
    /// Goal rectangle length along the ego's last heading, m.
    #[arg(long, default_value_t = 50.0)]
    pub goal_length: f64,
    /// Goal rectangle width, m.
    #[arg(long, default_value_t = 10.0)]
    pub goal_width: f64,
    /// Goal time interval: this many steps before the ego's last step up to it.
    #[arg(long, default_value_t = 10)]
    pub goal_time_window: u64,
    /// Goal velocity interval: the ego's last speed ± this, m/s (clamped at 0).
    #[arg(long, default_value_t = 5.0)]
    pub goal_speed_margin: f64,
    /// No velocity interval in the goal.
    #[arg(long, conflicts_with = "goal_speed_margin")]
    pub no_goal_velocity: bool,
    /// Goal orientation interval: the ego's last heading ± this, rad (default: none).
    #[arg(long, value_name = "RAD")]
    pub goal_orientation_margin: Option<f64>,
    /// Country code of the benchmark id: ZAM or an ISO 3166 alpha-3 code (e.g. DEU).
    #[arg(long, default_value = "ZAM")]
    pub country: String,
    /// Author attribute (default: the OpenSCENARIO FileHeader's author).
    #[arg(long)]
    pub author: Option<String>,
    /// Affiliation attribute.
    #[arg(long, default_value = "")]
    pub affiliation: String,
    /// Source attribute (default: "OpenSCENARIO <file>, converted by osc2cr").
    #[arg(long)]
    pub source: Option<String>,
    /// Date attribute, YYYY-MM-DD (default: the FileHeader's date, else 1970-01-01 — never
    /// today, so the same input gives the same bytes).
    #[arg(long, value_parser = convert::parse_date)]
    pub date: Option<commonroad::Date>,
    /// Most variations converted per parameter distribution file.
    #[arg(long, default_value_t = 100)]
    pub max_variations: u64,
    /// Largest distance between a lanelet bound and the exact lane border, m (default: the
    /// map converter's, 0.005); coarser gives fewer points and smaller files.
    #[arg(long, value_name = "METRES")]
    pub map_tolerance: Option<f64>,
    /// Seed for stochastic parameter distributions (default: the file's own).
    #[arg(long)]
    pub seed: Option<u64>,
    /// Seed of esmini's random generator in the engine (esmini's --seed; 0 as in the reference
    /// traces). It decides ties esmini leaves to chance, e.g. between two equally turning
    /// junction arms.
    #[arg(long, default_value_t = 0, value_name = "N")]
    pub engine_seed: u32,
    /// Scenarios converted in parallel (default: the number of CPUs).
    #[arg(short = 'j', long = "jobs")]
    pub jobs: Option<usize>,
    /// Wall-clock limit per scenario, s.
    #[arg(long, default_value_t = 60.0, value_name = "SECS")]
    pub timeout: f64,
    /// Convert only part K of N of the work (scenarios and variations, in a fixed order; K from
    /// 1): the N shards together write exactly the files of one run without --shard.
    #[arg(long, value_name = "K/N")]
    pub shard: Option<convert::Shard>,
    /// Also write a PNG picture of each converted scenario beside it (same name, .png): the
    /// roads, the obstacles at the first time step, the ego and its goal region.
    #[arg(long)]
    pub render: bool,
    /// Write a JSON report (per scenario: status, failure, warnings, timings, counts, …).
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Print every warning on stderr.
    #[arg(short, long)]
    pub verbose: bool,
    /// Read references to what does not exist (an undeclared entity, storyboard element,
    /// parameter or variable; a road or lane the map does not have; a parameter override the
    /// scenario does not declare) and distributions that cannot be sampled (negative variance,
    /// empty range, …) as warnings and convert anyway, as osc2cr did before 0.2. By default
    /// each is an error naming file:line:col, and the file is not written.
    #[arg(long)]
    pub lenient: bool,
}

pub(crate) fn parse_param(s: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((n, v)) if !n.trim().is_empty() => Ok((n.trim().to_string(), v.to_string())),
        _ => Err(format!("expected NAME=VALUE, got {s:?}")),
    }
}

fn options(args: &ConvertArgs) -> ConvertOptions {
    ConvertOptions {
        dt: args.dt,
        step: args.step,
        max_time: args.max_time,
        ego: match &args.ego {
            Some(n) => EgoChoice::Name(n.clone()),
            None => EgoChoice::Pattern(args.ego_pattern.clone()),
        },
        drop_ego: args.drop_ego,
        goal: GoalOptions {
            length: args.goal_length,
            width: args.goal_width,
            time_window: args.goal_time_window,
            speed_margin: (!args.no_goal_velocity).then_some(args.goal_speed_margin),
            orientation_margin: args.goal_orientation_margin,
        },
        country: args.country.clone(),
        author: args.author.clone(),
        affiliation: args.affiliation.clone(),
        source: args.source.clone(),
        date: args.date,
        parameters: args.params.clone(),
        seed: args.seed,
        max_variations: args.max_variations,
        map_tolerance: args.map_tolerance,
        engine_seed: args.engine_seed,
        deadline: None,
        lenient: args.lenient,
    }
}

/// A progress bar on stderr when it is a terminal; nothing otherwise.
struct Bar(indicatif::ProgressBar);

impl convert::Progress for Bar {
    fn start(&self, total: usize) {
        self.0.set_length(total as u64);
    }
    fn done(&self, report: &ScenarioReport) {
        self.0.set_message(report.input.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default());
        self.0.inc(1);
    }
}

fn bar() -> Bar {
    if !std::io::stderr().is_terminal() {
        return Bar(indicatif::ProgressBar::hidden());
    }
    let b = indicatif::ProgressBar::new(0);
    if let Ok(style) = indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {elapsed} {wide_msg}") {
        b.set_style(style);
    }
    Bar(b)
}

pub fn run(args: &ConvertArgs) -> Result<(), Failure> {
    let options = options(args);
    options.check().map_err(Failure::input)?;
    if !(args.timeout.is_finite() && args.timeout > 0.0) {
        return Err(Failure::input(format!("--timeout must be a positive number of seconds, got {}", args.timeout)));
    }
    let jobs = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()))
        .max(1);
    let batch = BatchOptions { out_dir: args.output.clone(), jobs, timeout: Some(Duration::from_secs_f64(args.timeout)), shard: args.shard, render: args.render };
    let bar = bar();
    let report = convert::run_batch(&args.inputs, &options, &batch, &bar).map_err(Failure::input)?;
    bar.0.finish_and_clear();

    for s in &report.skipped {
        eprintln!("skipped {}: {}", s.path.display(), s.reason);
    }
    for r in &report.scenarios {
        let what = match &r.variation {
            Some(v) => format!("{} (variation {})", r.input.display(), v.index),
            None => r.input.display().to_string(),
        };
        if let Some(f) = &r.failure {
            eprintln!("failed {what}: {} stage: {}", stage_name(f.stage), f.message);
        }
        if args.verbose {
            for w in &r.warnings {
                eprintln!("warning {what}: {}: {}", stage_name(w.stage), w.message);
            }
        }
    }
    if let Some(path) = &args.report {
        let json = serde_json::to_vec_pretty(&report).map_err(|e| Failure::input(format!("report: {e}")))?;
        commonroad::xml::write_atomic(path, &json).map_err(|e| Failure::input(e.to_string()))?;
    }
    print!("{}", convert::render_summary(&report.summary));
    let failed = report.failed();
    let warnings: usize = report.scenarios.iter().map(|r| r.warnings.len()).sum();
    eprintln!(
        "{} converted, {} failed, {} skipped, {} warnings{} -> {}",
        report.scenarios.len() - failed,
        failed,
        report.skipped.len(),
        warnings,
        if args.verbose || warnings == 0 { "" } else { " (-v lists them)" },
        args.output.display()
    );
    if report.planned == 0 {
        return Err(Failure::input("no scenario to convert among the inputs"));
    }
    if failed > 0 {
        // One file given, and it is malformed or refers to what does not exist: bad input (2),
        // also when that file is a distribution whose variations run as a batch. A folder or
        // several files of which some failed: a partial batch (1).
        let single = args.inputs.len() == 1 && args.inputs[0].is_file();
        let bad_input = single
            && report
                .scenarios
                .iter()
                .any(|r| r.failure.as_ref().is_some_and(|f| matches!(f.stage, Stage::Load | Stage::RoadNetwork)));
        return Err(Failure {
            message: format!("{failed} of {} scenarios failed", report.scenarios.len()),
            status: if bad_input { 2 } else { 1 },
        });
    }
    debug_assert!(report.scenarios.iter().all(|r| r.status == Status::Converted));
    Ok(())
}

fn stage_name(s: Stage) -> &'static str {
    match s {
        Stage::Load => "load",
        Stage::RoadNetwork => "road network",
        Stage::Map => "map",
        Stage::Engine => "engine",
        Stage::Build => "build",
        Stage::Write => "write",
        Stage::Timeout => "timeout",
        Stage::Render => "render",
    }
}

//! `osc2cr convert`: OpenSCENARIO files and folders in, one CommonRoad scenario per scenario
//! (and per parameter variation) out — a 2020a XML file, or the 2024 format's scenario and
//! dynamic files with one map per lanelet network — with a summary table, an optional JSON
//! report and TSV table written as the batch goes, and a progress bar on a terminal. All the
//! work is `convert::run_batch_streaming`; this maps options and results.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Duration;

use convert::{BatchOptions, ConvertOptions, EgoChoice, GoalOptions, JsonReport, OutputFormat, ScenarioReport, Stage, Table};

use crate::failure::Failure;
use crate::shared_options::{CommonRoadArgs, RunArgs};

#[derive(clap::Args)]
pub(crate) struct ConvertArgs {
    /// Scenario files (.xosc, parameter distributions included) and folders to search.
    #[arg(required = true, value_name = "FILE_OR_DIR")]
    pub inputs: Vec<PathBuf>,
    /// Output folder (created if missing); folders given as input keep their layout inside it.
    #[arg(short, long, value_name = "OUT_DIR")]
    pub output: PathBuf,
    /// CommonRoad format: 2020a (one XML file per scenario, what most tools read) or 2024
    /// (protobuf, read by commonroad-io 2026's three-file reader: per scenario NAME-SC.pb with
    /// the planning problems and NAME.pb with the obstacles, and one map file per distinct
    /// lanelet network, OUT_DIR/<map id>.pb, written once and shared — for parameter sweeps).
    #[arg(long, default_value = "2020a", value_name = "2020a|2024")]
    pub format: OutputFormat,
    #[command(flatten)]
    pub run: RunArgs,
    #[command(flatten)]
    pub output_file: CommonRoadArgs,
    /// The ego entity, by exact name (default: first by name containing --ego-pattern).
    #[arg(long, value_name = "NAME")]
    pub ego: Option<String>,
    /// Text the ego's name contains (case-insensitive); else the first moving entity is the ego.
    #[arg(long, default_value = "ego", value_name = "TEXT")]
    pub ego_pattern: String,
    /// Goal rectangle length along the ego's last heading, m.
    #[arg(long, default_value_t = 50.0, allow_negative_numbers = true)]
    pub goal_length: f64,
    /// Goal rectangle width, m.
    #[arg(long, default_value_t = 10.0, allow_negative_numbers = true)]
    pub goal_width: f64,
    /// Goal time interval: this many steps before the ego's last step up to it.
    #[arg(long, default_value_t = 10, allow_negative_numbers = true, value_parser = crate::shared_options::whole::<u64>)]
    pub goal_time_window: u64,
    /// Goal velocity interval: the ego's last speed ± this, m/s (clamped at 0).
    #[arg(long, default_value_t = 5.0, allow_negative_numbers = true)]
    pub goal_speed_margin: f64,
    /// No velocity interval in the goal.
    #[arg(long, conflicts_with = "goal_speed_margin")]
    pub no_goal_velocity: bool,
    /// Goal orientation interval: the ego's last heading ± this, rad (default: none).
    #[arg(long, value_name = "RAD", allow_negative_numbers = true)]
    pub goal_orientation_margin: Option<f64>,
    /// Country code of the benchmark id, ZAM or an ISO 3166 alpha-3 code (e.g. DEU, SWE); also
    /// the country of signals that name none (ZAM: the German catalogue of the OpenDRIVE
    /// annex), as for map.
    #[arg(long, default_value = "ZAM", value_name = "CODE")]
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
    /// Most variations converted per parameter distribution file (for a whole sweep, its
    /// number of variations or more).
    #[arg(long, default_value_t = 100, allow_negative_numbers = true, value_parser = crate::shared_options::whole::<u64>)]
    pub max_variations: u64,
    /// Largest distance between a lanelet bound and the exact lane border, m (default: the
    /// map converter's, 0.005); coarser gives fewer points and smaller files.
    #[arg(long, value_name = "METRES", allow_negative_numbers = true)]
    pub map_tolerance: Option<f64>,
    /// Seed for stochastic parameter distributions (default: the file's own).
    #[arg(long, allow_negative_numbers = true, value_parser = crate::shared_options::whole::<u64>)]
    pub seed: Option<u64>,
    /// Scenarios converted in parallel (default: the number of CPUs).
    #[arg(short = 'j', long = "jobs", allow_negative_numbers = true, value_parser = crate::shared_options::whole::<usize>)]
    pub jobs: Option<usize>,
    /// Wall-clock limit per scenario, s.
    #[arg(long, default_value_t = 60.0, value_name = "SECS", allow_negative_numbers = true)]
    pub timeout: f64,
    /// Convert only part K of N of the work (scenarios and variations, in a fixed order; K from
    /// 1): the N shards together write exactly the files of one run without --shard.
    #[arg(long, value_name = "K/N")]
    pub shard: Option<convert::Shard>,
    /// Also write a PNG picture of each converted scenario beside it (same name, .png): the
    /// roads, the obstacles at the first time step, the ego and its goal region.
    #[arg(long)]
    pub render: bool,
    /// Write a JSON report (per scenario: status, failure, warnings, timings, counts, …),
    /// streamed to disk as the batch goes and put in place when it ends.
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Write a table, one tab-separated line per conversion in batch order (status, stage,
    /// files, lanelets, obstacles, duration, time, warnings, failure, parameters), line by line
    /// as the batch goes: the compact report of a large sweep.
    #[arg(long, value_name = "FILE")]
    pub table: Option<PathBuf>,
    /// Continue an interrupted run of the same command: a conversion whose output files are all
    /// there is not converted again (reported "complete"); temporary files the interrupted run
    /// left are removed. The result is the files of an uninterrupted run.
    #[arg(long)]
    pub resume: bool,
    /// Print the warnings on stderr: a warning repeated in one file once, at its first position,
    /// with how many more there are; `-vv` prints every one (the JSON report keeps them all).
    #[arg(short, long, action = clap::ArgAction::Count)]
    pub verbose: u8,
    /// Also write each run as an OSI trace file (ASAM OSI 3.5 GroundTruth per frame, as esmini's
    /// --osi_file writes it): FILE for one scenario file, else `<FILE stem>_<output name>.osi`
    /// beside FILE, one per scenario or variation.
    #[arg(long, value_name = "FILE")]
    pub osi_file: Option<PathBuf>,
}

fn options(args: &ConvertArgs) -> ConvertOptions {
    ConvertOptions {
        dt: args.output_file.dt,
        ego: match &args.ego {
            Some(n) => EgoChoice::Name(n.clone()),
            None => EgoChoice::Pattern(args.ego_pattern.clone()),
        },
        drop_ego: args.output_file.drop_ego,
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
        date: args.output_file.date,
        seed: args.seed,
        max_variations: args.max_variations,
        map_tolerance: args.map_tolerance,
        deadline: None,
        format: args.format,
        ..args.run.convert_options()
    }
}

/// A progress bar on stderr when it is a terminal (conversions per second and the time left);
/// nothing otherwise.
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
    if let Ok(style) = indicatif::ProgressStyle::with_template("{bar:30} {pos}/{len} {per_sec} {elapsed}, {eta} left {wide_msg}") {
        b.set_style(style);
    }
    Bar(b)
}

fn describe(r: &ScenarioReport) -> String {
    match &r.variation {
        Some(v) => format!("{} (variation {})", r.input.display(), v.index),
        None => r.input.display().to_string(),
    }
}

pub(crate) fn run(args: &ConvertArgs) -> Result<(), Failure> {
    let options = options(args);
    options.check().map_err(Failure::input)?;
    if !(args.timeout.is_finite() && args.timeout > 0.0) {
        return Err(Failure::input(format!("--timeout must be a positive number of seconds, got {}", args.timeout)));
    }
    let jobs = args.jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())).max(1);
    let batch = BatchOptions {
        out_dir: args.output.clone(),
        jobs,
        timeout: Some(Duration::from_secs_f64(args.timeout)),
        shard: args.shard,
        render: args.render,
        resume: args.resume,
    };
    let mut json = args.report.as_deref().map(JsonReport::create).transpose().map_err(Failure::input)?;
    let mut table = args.table.as_deref().map(Table::create).transpose().map_err(Failure::input)?;
    let mut report_error: Option<String> = None;
    let bar = bar();
    let traces = args.osi_file.as_deref().map(|file| crate::osi_file::ConvertTraces { file, single: args.inputs.len() == 1 && args.inputs[0].is_file() });
    let mut sink = |position: usize, r: ScenarioReport| {
        if let (Some(t), true) = (&traces, r.failure.is_none() && r.output.is_some()) {
            if let Err(e) = t.write(&r, &options) {
                bar.0.suspend(|| eprintln!("failed {}: OSI trace: {e}", describe(&r)));
                report_error.get_or_insert(e);
            }
        }
        if let Some(f) = &r.failure {
            bar.0.suspend(|| eprintln!("failed {}: {} stage: {}", describe(&r), stage_name(f.stage), f.message));
        }
        if args.verbose > 1 {
            for w in &r.warnings {
                bar.0.suspend(|| eprintln!("warning {}: {}: {}", describe(&r), stage_name(w.stage), w.message));
            }
        } else if args.verbose == 1 {
            let kinds = crate::grouped::by_kind(&r.warnings, |w| {
                let (file, kind) = crate::grouped::split_position(&w.message);
                (w.stage.as_str(), file.to_string(), crate::grouped::kind(kind))
            });
            for (w, more) in kinds {
                bar.0.suspend(|| eprintln!("warning {}: {}: {}{}", describe(&r), stage_name(w.stage), w.message, crate::grouped::more(more)));
            }
        }
        let written = json.as_mut().map_or(Ok(()), |j| j.add(&r)).and_then(|()| table.as_mut().map_or(Ok(()), |t| t.add(position, &r)));
        if let Err(e) = written {
            report_error.get_or_insert(e);
        }
    };
    let totals = convert::run_batch_streaming(&args.inputs, &options, &batch, &bar, &mut sink).map_err(Failure::input)?;
    bar.0.finish_and_clear();
    if let Some(e) = report_error {
        return Err(Failure::input(e));
    }
    if let Some(j) = json {
        j.finish(&totals.skipped, &totals.summary, totals.planned).map_err(Failure::input)?;
    }

    for s in &totals.skipped {
        eprintln!("skipped {}: {}", s.path.display(), s.reason);
    }
    if !totals.removed_temporaries.is_empty() {
        eprintln!("removed {} temporary file(s) an interrupted run left", totals.removed_temporaries.len());
    }
    // a table of nothing but failures says no more than the failures above and the line below
    if totals.converted + totals.complete > 0 {
        print!("{}", convert::render_summary(&totals.summary));
    }
    let complete = if totals.complete > 0 { format!(", {} already complete (--resume)", totals.complete) } else { String::new() };
    eprintln!(
        "{} converted{complete}, {} failed, {} skipped, {} warnings{} -> {}",
        totals.converted,
        totals.failed,
        totals.skipped.len(),
        totals.warnings,
        if args.verbose > 0 || totals.warnings == 0 { "" } else { " (-v lists them)" },
        args.output.display()
    );
    if totals.planned == 0 {
        return Err(Failure::input("no scenario to convert among the inputs"));
    }
    if totals.failed > 0 {
        // One file given, and it is malformed or refers to what does not exist: bad input (2),
        // also when that file is a distribution whose variations run as a batch. A folder or
        // several files of which some failed: a partial batch (1).
        let single = args.inputs.len() == 1 && args.inputs[0].is_file();
        let conversions = totals.converted + totals.failed + totals.complete;
        return Err(Failure {
            message: format!("{} of {conversions} scenarios failed", totals.failed),
            status: if single && totals.input_failed { 2 } else { 1 },
        });
    }
    Ok(())
}

/// A stage as messages name it: the report's name with spaces (`road network`).
pub(crate) fn stage_name(s: Stage) -> String {
    s.as_str().replace('_', " ")
}

//! `osc2cr simulate`: run a scenario with the engine and write its trace as CSV (the columns are
//! in `--trace`'s help; esmini's `--csv_logger` has the same quantities), optionally the
//! storyboard events; warnings go to stderr with -v.

use crate::failure::Failure;
use crate::shared_options::RunArgs;
use std::fmt::Write as _;
use std::path::PathBuf;

#[derive(clap::Args)]
pub(crate) struct SimulateArgs {
    /// The OpenSCENARIO file (.xosc).
    pub file: PathBuf,
    /// Where to write the trace: CSV, one row per entity and engine step, with the columns
    /// time (s), entity (its name), x, y, z (m: the entity's reference point, its OpenSCENARIO
    /// position, in the map's coordinates), h (heading, rad), speed (m/s), bb_cx, bb_cy, bb_cz
    /// (the bounding box's centre relative to the reference point, m), length, width, height
    /// (m), lane_id, lane_offset (m), s (m along the road; the last three empty off the road).
    /// An entity added later or deleted has no rows while it is absent; where a ghost restarts,
    /// the rows of the rewound time follow and the time goes back.
    #[arg(long, value_name = "OUT.csv")]
    pub trace: PathBuf,
    #[command(flatten)]
    pub run: RunArgs,
    /// Also write the storyboard's state transitions as CSV with the columns time (s), element
    /// (its kind and name), from, transition, to (the states and the transition between them).
    #[arg(long, value_name = "OUT.csv")]
    pub events: Option<PathBuf>,
    /// Also write the run as an OSI trace file (ASAM OSI 3.5 GroundTruth per frame, as esmini's
    /// --osi_file writes it).
    #[arg(long, value_name = "FILE")]
    pub osi_file: Option<PathBuf>,
    /// Print the warnings on stderr.
    #[arg(short, long)]
    pub verbose: bool,
}

/// Problems a strict reading rejects: an error listing them all, or warnings with --lenient.
fn strict<T: ToString>(problems: Vec<T>, lenient: bool, warnings: &mut Vec<String>) -> Result<(), Failure> {
    if problems.is_empty() {
        return Ok(());
    }
    let list: Vec<String> = problems.iter().map(ToString::to_string).collect();
    if lenient {
        warnings.extend(list);
        return Ok(());
    }
    Err(Failure::input(format!("{} reference(s) to what does not exist (--lenient reads them as warnings):\n{}", list.len(), list.join("\n"))))
}

fn write_file(path: &std::path::Path, text: &str) -> Result<(), Failure> {
    commonroad::xml::write_atomic(path, text.as_bytes()).map_err(|e| Failure { message: format!("{}: {e}", path.display()), status: 1 })
}

pub(crate) fn run(args: &SimulateArgs) -> Result<(), Failure> {
    let options = openscenario::LoadOptions { parameters: args.run.params.values.clone(), seed: None, ..Default::default() };
    let loaded = crate::scenario_input::load(&args.file, &options)?;
    let mut load_warnings: Vec<String> = loaded.warnings.iter().map(ToString::to_string).collect();
    strict(loaded.problems, args.run.lenient, &mut load_warnings)?;
    let scenario = match loaded.content {
        openscenario::Content::Scenario(s) => *s,
        _ => return Err(Failure::input(format!("{}: not a scenario (a distribution or catalog file)", args.file.display()))),
    };
    let (roads, road_warnings) = match crate::scenario_input::road_network(&scenario)? {
        Some(l) => (Some(l.network), l.warnings),
        None => (None, Vec::new()),
    };
    strict(engine::road_references(&scenario, roads.as_ref()), args.run.lenient, &mut load_warnings)?;
    let settings = engine::Settings { step: args.run.step, max_time: args.run.max_time };
    let control = engine::RunControl { seed: args.run.engine_seed, deadline: None };
    let run = engine::simulate_with(&scenario, roads.as_ref(), &settings, &control).map_err(|e| Failure::input(e.to_string()))?;
    write_file(&args.trace, &run.trace.to_csv(&engine::bounding_boxes(&scenario)))?;
    if let Some(ev) = &args.events {
        let mut text = String::from("time,element,from,transition,to\n");
        for e in &run.trace.events {
            let _ = writeln!(text, "{:.3},{},{},{},{}", e.time, e.element, e.from, e.transition, e.to);
        }
        write_file(ev, &text)?;
    }
    if let Some(path) = &args.osi_file {
        load_warnings.extend(crate::osi_file::write_trace(path, &scenario, roads.as_ref(), &run.trace)?);
    }
    let n_warn = load_warnings.len() + road_warnings.len() + run.warnings.len();
    if args.verbose {
        for w in &load_warnings {
            eprintln!("{w}");
        }
        for w in &road_warnings {
            eprintln!("{}", w.labelled("warning"));
        }
        for w in &run.warnings {
            eprintln!("{w}");
        }
    }
    eprintln!(
        "{}: {:.2} s simulated, {} entities, {} warnings{} -> {}",
        args.file.display(),
        run.trace.duration(),
        run.trace.entities.len(),
        n_warn,
        if args.verbose || n_warn == 0 { "" } else { " (-v lists them)" },
        args.trace.display()
    );
    Ok(())
}

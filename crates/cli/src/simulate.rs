//! `osc2cr simulate`: run a scenario with the engine and write its trace (the CSV format of
//! `conformance.py`), optionally the storyboard events; warnings go to stderr with -v.

use crate::Failure;
use std::fmt::Write as _;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct SimulateArgs {
    /// The OpenSCENARIO file (.xosc).
    pub file: PathBuf,
    /// Where to write the trace (CSV: time,entity,x,y,z,h,speed,...).
    #[arg(long)]
    pub trace: PathBuf,
    /// Engine step, s.
    #[arg(long, default_value_t = 0.01)]
    pub step: f64,
    /// Maximum simulated time, s.
    #[arg(long, default_value_t = 60.0)]
    pub max_time: f64,
    /// Override a global parameter (repeatable): --param NAME=VALUE.
    #[arg(long = "param", value_name = "NAME=VALUE")]
    pub params: Vec<String>,
    /// Seed of esmini's random generator (esmini's --seed; 0 as in the reference traces). It
    /// decides what esmini leaves to chance, e.g. which of two equally turning junction arms
    /// an entity takes.
    #[arg(long, default_value_t = 0, value_name = "N")]
    pub engine_seed: u32,
    /// Also write the storyboard state transitions (time,element,from,transition,to).
    #[arg(long)]
    pub events: Option<PathBuf>,
    /// Also write the run as an OSI trace file (ASAM OSI 3.5 GroundTruth per frame, as esmini's
    /// --osi_file writes it).
    #[arg(long, value_name = "FILE")]
    pub osi_file: Option<PathBuf>,
    /// Print the warnings on stderr.
    #[arg(short, long)]
    pub verbose: bool,
    /// Read references to what does not exist (entities, storyboard elements, parameters,
    /// variables, roads, lanes) as warnings and run anyway; by default each is an error naming
    /// file:line:col and no trace is written.
    #[arg(long)]
    pub lenient: bool,
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

fn parse_param(p: &str) -> Result<(String, String), Failure> {
    match p.split_once('=') {
        Some((n, v)) if !n.trim().is_empty() => Ok((n.trim().to_string(), v.to_string())),
        _ => Err(Failure::input(format!("--param expects NAME=VALUE, got '{p}'"))),
    }
}

fn write_file(path: &std::path::Path, text: &str) -> Result<(), Failure> {
    commonroad::xml::write_atomic(path, text.as_bytes()).map_err(|e| Failure { message: format!("{}: {e}", path.display()), status: 1 })
}

pub fn run(args: &SimulateArgs) -> Result<(), Failure> {
    let parameters = args.params.iter().map(|p| parse_param(p)).collect::<Result<Vec<_>, _>>()?;
    let options = openscenario::LoadOptions { parameters, seed: None, ..Default::default() };
    let loaded = openscenario::load(&args.file, &options).map_err(|e| Failure::input(e.to_string()))?;
    let mut load_warnings: Vec<String> = loaded.warnings.iter().map(ToString::to_string).collect();
    strict(loaded.problems, args.lenient, &mut load_warnings)?;
    let scenario = match loaded.content {
        openscenario::Content::Scenario(s) => *s,
        _ => return Err(Failure::input(format!("{}: not a scenario (a distribution or catalog file)", args.file.display()))),
    };
    let (roads, road_warnings) = match &scenario.road_network.logic_file {
        Some(p) => {
            let l = opendrive::load(p).map_err(|e| Failure::input(e.to_string()))?;
            (Some(l.network), l.warnings)
        }
        None => (None, Vec::new()),
    };
    strict(engine::road_references(&scenario, roads.as_ref()), args.lenient, &mut load_warnings)?;
    let settings = engine::Settings { step: args.step, max_time: args.max_time };
    let control = engine::RunControl { seed: args.engine_seed, deadline: None };
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
            eprintln!("{w}");
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

//! `osc2cr export`: CommonRoad scenarios (2018b/2020a XML, 2024 protobuf) and folders in, per
//! scenario an OpenSCENARIO file and one OpenDRIVE file per distinct lanelet network out, with a
//! summary table and an optional JSON report. All the work is `export::run_batch`; this maps
//! options and results.

use std::path::PathBuf;

use export::{BatchOptions, EgoController, ExportOptions, OscVersion, Report, Status};

use crate::failure::Failure;

pub(crate) const ABOUT: &str = "Export CommonRoad scenarios as OpenSCENARIO + OpenDRIVE, for OpenSCENARIO simulators (esmini, CARLA, …) to replay.

Reads CommonRoad 2018b and 2020a XML files and the 2024 protobuf files (give the scenario file \
NAME-SC.pb; NAME.pb and the map <map id>.pb are found beside it or in a folder above). Folders are \
searched for both. Writes, per scenario, OUT_DIR/NAME.xosc (a folder's sub-folders are kept), and \
per distinct lanelet network one OpenDRIVE file OUT_DIR/<COUNTRY>_<hash>.xodr, named by its \
content and shared by every scenario on it.

In the scenario every obstacle is an entity of its CommonRoad type and shape (reference point: \
the box centre) that follows its trajectory exactly (a polyline vertex per state, absolute \
timing); obstacles that appear later or leave early are added and deleted at those times; static \
obstacles stand. Each planning problem places an ego (Ego) at its initial state: by default it \
keeps its lane and speed (--ego-controller external hands it to an outside driver, esmini's \
ExternalController). The goal becomes the end condition where OpenSCENARIO can say it (reaching \
it ends the run unless --play-to-end), and the planning problem itself is kept in a property of \
the ego, so `osc2cr convert` of the exported scenario gives it back. Traffic-light cycles become \
traffic-signal controllers. A simulator stepping at a divisor of the CommonRoad time step \
(e.g. esmini --fixed_timestep 0.01) hits every CommonRoad time step exactly.

A scenario that cannot be exported does not stop the batch: exit status 1 then (2 when the only \
file given is bad). Every file is written whole or not at all; the same input gives the same bytes.";

#[derive(clap::Args)]
pub(crate) struct ExportArgs {
    /// CommonRoad scenario files (.xml; 2024: NAME-SC.pb) and folders to search.
    #[arg(required = true, value_name = "FILE_OR_DIR")]
    pub inputs: Vec<PathBuf>,
    /// Output folder (created if missing).
    #[arg(short, long, value_name = "OUT_DIR")]
    pub output: PathBuf,
    /// OpenSCENARIO version written: 1.3, or 1.0 for simulators that read only 1.0 (CARLA's
    /// scenario_runner); with 1.0 only 1.0 constructs are written (no heading in goals).
    #[arg(long, default_value = "1.3", value_name = "1.3|1.0")]
    pub osc: OscVersion,
    /// Who drives the ego: default (keeps its lane and speed) or external (an outside driver,
    /// esmini's ExternalController, activated at the start).
    #[arg(long, default_value = "default", value_name = "default|external")]
    pub ego_controller: EgoController,
    /// Do not end the run when the egos reach their goals: play until every obstacle's
    /// trajectory and every goal's time window are over (a full replay).
    #[arg(long)]
    pub play_to_end: bool,
    /// Scenarios exported in parallel (default: the number of CPUs).
    #[arg(short = 'j', long = "jobs")]
    pub jobs: Option<usize>,
    /// Write a JSON report (per scenario: status, failure, warnings, what it holds, time; the
    /// maps with their warnings; the summary), whole, when the batch ends.
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Print every warning on stderr.
    #[arg(short, long)]
    pub verbose: bool,
}

pub(crate) fn run(args: &ExportArgs) -> Result<(), Failure> {
    let jobs = args.jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())).max(1);
    let options = BatchOptions {
        out_dir: args.output.clone(),
        jobs,
        export: ExportOptions { osc: args.osc, ego_controller: args.ego_controller, play_to_end: args.play_to_end },
    };
    let mut sink = |r: &Report| {
        if let Some(f) = &r.failure {
            eprintln!("failed {}: {}", r.input.display(), f.message);
        }
        if args.verbose {
            for w in &r.warnings {
                eprintln!("warning {}: {w}", r.input.display());
            }
        }
    };
    let totals = export::run_batch(&args.inputs, &options, &mut sink).map_err(Failure::input)?;
    if args.verbose {
        for m in &totals.maps {
            for w in &m.warnings {
                eprintln!("warning {}: {w}", m.file);
            }
        }
    }
    if let Some(path) = &args.report {
        totals.write(path).map_err(Failure::input)?;
    }
    for s in &totals.skipped {
        eprintln!("skipped {}: {}", s.path.display(), s.reason);
    }
    let cells: Vec<Vec<String>> = totals.summary.iter().map(export::SummaryRow::cells).collect();
    print!("{}", convert::render_table(&export::SummaryRow::HEADER, &cells));
    eprintln!(
        "{} exported, {} failed, {} skipped, {} map(s), {} warnings{} -> {}",
        totals.exported,
        totals.failed,
        totals.skipped.len(),
        totals.maps.len(),
        totals.warnings,
        if args.verbose || totals.warnings == 0 { "" } else { " (-v lists them)" },
        args.output.display()
    );
    if totals.reports.is_empty() {
        return Err(Failure::input("no CommonRoad scenario among the inputs"));
    }
    if totals.failed > 0 {
        let single = args.inputs.len() == 1 && args.inputs[0].is_file();
        let status = if single { 2 } else { 1 };
        let failed: Vec<&Report> = totals.reports.iter().filter(|r| r.status == Status::Failed).collect();
        return Err(Failure { message: format!("{} of {} scenarios failed", failed.len(), totals.reports.len()), status });
    }
    Ok(())
}

//! `difftest`: generate scenarios from a seed, run osc2cr's engine (and esmini, when given) on
//! each, and report agreement by feature. See crates/difftest/README.md.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Parser;

/// Differential testing of osc2cr's engine against esmini on generated OpenSCENARIO scenarios.
#[derive(Parser)]
#[command(version)]
struct Args {
    /// Seed of the generator: the same seed gives the same scenarios, byte for byte.
    #[arg(long)]
    seed: u64,
    /// Number of scenarios.
    #[arg(long, default_value_t = 100)]
    count: u64,
    /// Folder for the scenarios, the maps, both traces and the report (report.json).
    #[arg(long)]
    out: PathBuf,
    /// esmini binary (3.6.0) to compare with; without it osc2cr runs alone (crashes,
    /// rejections and warnings are still found).
    #[arg(long)]
    esmini: Option<PathBuf>,
    /// A folder of OpenDRIVE maps to place entities on besides the built-in straight and curved
    /// roads (e.g. ../shared/corpus).
    #[arg(long)]
    maps: Option<PathBuf>,
    /// Most maps taken from --maps.
    #[arg(long, default_value_t = 20)]
    max_maps: usize,
}

fn main() -> ExitCode {
    let a = Args::parse();
    let plan = difftest::Plan { seed: a.seed, count: a.count, out: a.out.clone(), esmini: a.esmini, maps: a.maps, max_maps: a.max_maps };
    let outcomes = match difftest::run(&plan, |i, o| {
        if o.verdict != Some(difftest::compare::Verdict::Exact) {
            eprintln!("{i:>5} {} {:?} {:?} {}", o.name, o.verdict, o.max_pos_err, o.note.as_deref().unwrap_or(""));
        }
    }) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let report = difftest::report::Report::new(a.seed, outcomes);
    print!("{}", report.table());
    match serde_json::to_vec_pretty(&report) {
        Ok(json) => {
            if let Err(e) = std::fs::write(a.out.join("report.json"), json) {
                eprintln!("error: report.json: {e}");
                return ExitCode::from(1);
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(1);
        }
    }
    ExitCode::SUCCESS
}

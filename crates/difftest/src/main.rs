//! `difftest`: generate scenarios from a seed, run osc2cr's engine (and esmini, when given) on
//! each, and report agreement by feature (`run`); the long measurement over several seeds
//! (`measure`); the coverage table (`coverage`). See crates/difftest/README.md.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use difftest::{coverage, generate, measure, report::Report};

/// Differential testing of osc2cr's engine against esmini on generated OpenSCENARIO scenarios.
#[derive(Parser)]
#[command(version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Generate and run one seed's scenarios.
    Run {
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
        /// A folder of OpenDRIVE maps to place entities on besides the built-in ones (e.g.
        /// ../shared/corpus).
        #[arg(long)]
        maps: Option<PathBuf>,
        /// Most maps taken from --maps.
        #[arg(long, default_value_t = 1000)]
        max_maps: usize,
        /// Run this osc2cr binary (`osc2cr simulate`) instead of this build's engine, e.g. a
        /// baseline release, on the same scenarios.
        #[arg(long)]
        osc2cr: Option<PathBuf>,
    },
    /// The long measurement: every seed without and (with --maps) with the folder's maps;
    /// writes each run's report, summary.txt, and the measured agreement per coverage element.
    Measure {
        #[arg(long, value_delimiter = ',', default_values_t = [101u64, 202, 303])]
        seeds: Vec<u64>,
        #[arg(long, default_value_t = 1000)]
        count: u64,
        #[arg(long)]
        out: PathBuf,
        #[arg(long)]
        esmini: PathBuf,
        #[arg(long)]
        maps: Option<PathBuf>,
        /// Where the measured agreement per element goes (the coverage table reads it).
        #[arg(long, default_value = concat!(env!("CARGO_MANIFEST_DIR"), "/measured.tsv"))]
        measured: PathBuf,
        /// Run this osc2cr binary instead of this build's engine (a baseline); give --measured
        /// elsewhere then, the coverage table is this build's.
        #[arg(long)]
        osc2cr: Option<PathBuf>,
    },
    /// The coverage table: print it, or write it (--write) where the test checks it.
    Coverage {
        #[arg(long, default_value = concat!(env!("CARGO_MANIFEST_DIR"), "/measured.tsv"))]
        measured: PathBuf,
        #[arg(long)]
        write: bool,
    },
}

fn write_report(out: &Path, report: &Report) -> Result<(), String> {
    let json = serde_json::to_vec_pretty(report).map_err(|e| e.to_string())?;
    std::fs::write(out.join("report.json"), json).map_err(|e| format!("{}: {e}", out.join("report.json").display()))
}

fn run_plan(plan: &difftest::Plan) -> Result<Report, String> {
    let outcomes = difftest::run(plan, |i, o| {
        if o.verdict != Some(difftest::compare::Verdict::Exact) {
            eprintln!("{i:>5} {} {:?} {:?} {}", o.name, o.verdict, o.max_pos_err, o.note.as_deref().unwrap_or(""));
        }
    })
    .map_err(|e| e.to_string())?;
    let report = Report::new(plan.seed, outcomes);
    write_report(&plan.out, &report)?;
    Ok(report)
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Run { seed, count, out, esmini, maps, max_maps, osc2cr } => run_plan(&difftest::Plan { seed, count, out, esmini, maps, max_maps, osc2cr })
            .map(|report| print!("{}", report.table(&format!("all (seed {seed})")))),
        Command::Measure { seeds, count, out, esmini, maps, measured, osc2cr } => (|| {
            let mut reports = Vec::new();
            let mut summary = String::new();
            for (label, plan) in measure::runs(&seeds, count, &out, &esmini, maps.as_deref(), osc2cr.as_deref()) {
                eprintln!("== {label}");
                let report = run_plan(&plan)?;
                let t = &report.total;
                summary.push_str(&format!(
                    "{label}: {} of {} compared agree ({:.1} %)\n",
                    t.exact + t.close,
                    t.exact + t.close + t.diverged,
                    100.0 * report.total.agreement().unwrap_or(0.0)
                ));
                reports.push((label, report));
            }
            let all = measure::combined(&reports);
            summary.push('\n');
            summary.push_str(&all.table("all runs"));
            std::fs::write(out.join("summary.txt"), &summary).map_err(|e| e.to_string())?;
            print!("{summary}");
            let runs = format!(
                "seeds {}, {count} scenarios each, {}",
                seeds.iter().map(u64::to_string).collect::<Vec<_>>().join(", "),
                if maps.is_some() { "without and with --maps" } else { "built-in maps" }
            );
            std::fs::write(&measured, coverage::write_measured(&runs, &measure::measured(&all.scenarios))).map_err(|e| e.to_string())
        })(),
        Command::Coverage { measured, write } => (|| {
            let dir = std::env::temp_dir().join(format!("difftest-coverage-{}", std::process::id()));
            std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
            let maps = generate::maps::builtin(&dir).map_err(|e| e.to_string())?;
            let generated = measure::generated_elements(measure::SAMPLE_SEED, measure::SAMPLE_COUNT, &maps);
            let _ = std::fs::remove_dir_all(&dir);
            let (runs, m) = coverage::read_measured(&std::fs::read_to_string(&measured).unwrap_or_default());
            let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
            let table = coverage::markdown(&coverage::rows(&crates, &generated), &runs, &m);
            if write {
                let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("COVERAGE.md");
                std::fs::write(&path, table).map_err(|e| format!("{}: {e}", path.display()))
            } else {
                print!("{table}");
                Ok(())
            }
        })(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

//! `difftest`: differential testing of osc2cr's engine against esmini 3.6.0. It owns a seeded
//! grammar of OpenSCENARIO scenarios and the maps they run on (`generate`), running esmini and
//! reading its log (`esmini`), the comparison with `conformance.py`'s thresholds (`compare`),
//! the agreement-by-feature report (`report`) and the coverage table of the OpenSCENARIO
//! elements the engine acts on (`coverage`). It runs offline and is deterministic for a seed;
//! without an esmini binary it still generates and runs osc2cr, which finds what crashes,
//! warns or is rejected.

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

pub mod compare;
pub mod coverage;
pub mod esmini;
pub mod generate;
pub mod measure;
pub mod report;

use std::path::{Path, PathBuf};
use std::time::Duration;

use compare::{State, TraceBuilder, Traces};
use report::Outcome;

/// What one run of the tool is asked to do.
#[derive(Debug, Clone)]
pub struct Plan {
    pub seed: u64,
    pub count: u64,
    pub out: PathBuf,
    pub esmini: Option<PathBuf>,
    /// A folder of OpenDRIVE maps to use besides the built-in ones.
    pub maps: Option<PathBuf>,
    pub max_maps: usize,
    /// An osc2cr binary to run instead of this build's engine (`osc2cr simulate`): measures
    /// another version (a baseline) on the same scenarios.
    pub osc2cr: Option<PathBuf>,
}

/// osc2cr's run of a scenario: its states per entity and the engine's warnings.
#[derive(Debug, Clone, PartialEq)]
pub struct Osc2crRun {
    pub traces: Traces,
    pub warnings: Vec<String>,
}

/// osc2cr's engine on `xosc`, as states per entity (the trace CSV is written beside it and
/// read back, so both sides go through the same reduction).
pub fn run_osc2cr(xosc: &Path) -> Result<Osc2crRun, String> {
    let loaded = openscenario::load(xosc, &Default::default()).map_err(|e| e.to_string())?;
    if let Some(p) = loaded.problems.first() {
        return Err(format!("rejected: {p}"));
    }
    let openscenario::Content::Scenario(scenario) = loaded.content else { return Err("not a scenario".into()) };
    let road = match &scenario.road_network.logic_file {
        Some(f) => Some(opendrive::network::load(f).map_err(|e| e.to_string())?.network),
        None => None,
    };
    let run = engine::simulate(&scenario, road.as_ref(), &engine::Settings::default()).map_err(|e| e.to_string())?;
    let csv = run.trace.to_csv(&engine::bounding_boxes(&scenario));
    let _ = std::fs::write(xosc.with_extension("osc2cr.csv"), &csv);
    let warnings = loaded.warnings.iter().map(|w| w.to_string()).chain(run.warnings.iter().map(|w| w.to_string())).collect();
    Ok(Osc2crRun { traces: parse_trace_csv(&csv), warnings })
}

/// An osc2cr binary's run of `xosc` (`simulate --trace … -v`): its trace, and its warnings
/// from stderr. A binary that fails names its exit status and first stderr line.
pub fn run_osc2cr_binary(bin: &Path, xosc: &Path) -> Result<Osc2crRun, String> {
    let trace = xosc.with_extension("osc2cr.csv");
    let out = std::process::Command::new(bin)
        .arg("simulate")
        .arg(xosc)
        .arg("--trace")
        .arg(&trace)
        .arg("-v")
        .output()
        .map_err(|e| format!("{}: {e}", bin.display()))?;
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        return Err(format!("{}: {}", out.status, stderr.lines().next().unwrap_or("")));
    }
    let csv = std::fs::read_to_string(&trace).map_err(|e| format!("{}: {e}", trace.display()))?;
    // its last line is the run's summary ("… simulated, … -> TRACE"), not a warning
    let warnings = stderr.lines().filter(|l| !l.ends_with(".osc2cr.csv")).map(str::to_string).collect();
    Ok(Osc2crRun { traces: parse_trace_csv(&csv), warnings })
}

/// The engine's trace CSV (`time,entity,x,y,z,h,speed,…`) as states per entity.
pub fn parse_trace_csv(csv: &str) -> Traces {
    let mut out = TraceBuilder::default();
    for line in csv.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        let num = |i: usize| f.get(i).and_then(|v| v.parse::<f64>().ok());
        if let (Some(t), Some(name), Some(x), Some(y), Some(h), Some(v)) = (num(0), f.get(1), num(2), num(3), num(5), num(6)) {
            out.push(name, State { t: (t * 100.0).round() / 100.0, x, y, h, v });
        }
    }
    out.finish()
}

/// The files below `dir` (recursively) whose extension is `ext` (any case), in path order.
pub fn files_with_ext(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case(ext)) {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// Generates, runs and compares the plan's scenarios; the outcomes in order.
pub fn run(plan: &Plan, mut progress: impl FnMut(u64, &Outcome)) -> std::io::Result<Vec<Outcome>> {
    std::fs::create_dir_all(&plan.out)?;
    // esmini runs in the scenario's folder: every path it gets must be absolute
    let out = std::fs::canonicalize(&plan.out)?;
    let esmini_path = plan.esmini.as_ref().map(|e| std::fs::canonicalize(e).unwrap_or_else(|_| e.clone()));
    let mut maps = generate::maps::builtin(&out)?;
    if let Some(dir) = &plan.maps {
        maps.extend(generate::maps::from_folder(dir, plan.max_maps));
    }
    let mut outcomes = Vec::new();
    for i in 0..plan.count {
        let g = generate::generate(plan.seed, i, &maps);
        let path = out.join(format!("{}.xosc", g.name));
        std::fs::write(&path, &g.xosc)?;
        let mut o = Outcome {
            name: path.file_name().map(|n| n.to_string_lossy().to_string()).unwrap_or_default(),
            features: g.features.iter().cloned().collect(),
            verdict: None,
            max_pos_err: None,
            ref_end: None,
            our_end: None,
            note: None,
            elements: coverage::elements_in(&g.xosc).into_iter().collect(),
            esmini_errors: Vec::new(),
            osc2cr_warnings: Vec::new(),
            size: g.xosc.len(),
        };
        let ours = match &plan.osc2cr {
            Some(bin) => run_osc2cr_binary(bin, &path),
            None => run_osc2cr(&path),
        };
        match ours {
            Err(e) => o.note = Some(format!("osc2cr: {e}")),
            Ok(ours) => {
                o.osc2cr_warnings = ours.warnings.clone();
                if let Some(esmini) = &esmini_path {
                    match esmini::run(esmini, &path, &path.with_extension("esmini.csv"), Duration::from_secs(60)) {
                        Err(e) => o.note = Some(e),
                        Ok(reference) => {
                            let c = compare::compare(&reference.traces, &ours.traces);
                            o.esmini_errors = reference.log_errors;
                            o.verdict = Some(c.verdict);
                            o.max_pos_err = c.max_pos_err;
                            o.ref_end = Some(c.ref_end);
                            o.our_end = Some(c.our_end);
                            if let Some((entity, t)) = c.worst {
                                o.note = Some(format!("largest error: {entity} at {t:.2} s"));
                            }
                        }
                    }
                }
            }
        }
        progress(i, &o);
        outcomes.push(o);
    }
    Ok(outcomes)
}

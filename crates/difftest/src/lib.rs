//! `difftest`: differential testing of osc2cr's engine against esmini 3.6.0. It owns a seeded
//! grammar of OpenSCENARIO scenarios (`generate`), the maps they run on (`roads`), running
//! esmini and reading its log (`esmini`), the comparison with `conformance.py`'s thresholds
//! (`compare`) and the agreement-by-feature report (`report`). It runs offline and is
//! deterministic for a seed; without an esmini binary it still generates and runs osc2cr,
//! which finds what crashes, warns or is rejected.

// A library returns its warnings as data and never prints (ARCHITECTURE.md, Invariants); its
// unit tests may.
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

pub mod compare;
pub mod esmini;
pub mod generate;
pub mod report;
pub mod roads;

use std::path::{Path, PathBuf};
use std::time::Duration;

use compare::{State, Traces};
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
}

/// osc2cr's engine on `xosc`, as states per entity (the trace CSV is written beside it).
pub fn run_osc2cr(xosc: &Path) -> Result<Traces, String> {
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
    let trace = &run.trace;
    let _ = std::fs::write(xosc.with_extension("osc2cr.csv"), trace.to_csv(&engine::bounding_boxes(&scenario)));
    let mut out = Traces::new();
    for e in &trace.entities {
        let states: Vec<State> = e
            .samples
            .iter()
            .enumerate()
            .filter_map(|(k, s)| s.map(|s| State { t: (trace.time(k) * 100.0).round() / 100.0, x: s.x, y: s.y, h: s.h, v: s.speed }))
            .collect();
        out.insert(e.name.clone(), states);
    }
    Ok(out)
}

/// Generates, runs and compares the plan's scenarios; the outcomes in order.
pub fn run(plan: &Plan, mut progress: impl FnMut(u64, &Outcome)) -> std::io::Result<Vec<Outcome>> {
    std::fs::create_dir_all(&plan.out)?;
    // esmini runs in the scenario's folder: every path it gets must be absolute
    let out = std::fs::canonicalize(&plan.out)?;
    let esmini_path = plan.esmini.as_ref().map(|e| std::fs::canonicalize(e).unwrap_or_else(|_| e.clone()));
    let mut maps = roads::builtin(&out)?;
    if let Some(dir) = &plan.maps {
        maps.extend(roads::from_folder(dir, plan.max_maps));
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
            size: g.xosc.len(),
        };
        match run_osc2cr(&path) {
            Err(e) => o.note = Some(format!("osc2cr: {e}")),
            Ok(ours) => {
                if let Some(esmini) = &esmini_path {
                    match esmini::run(esmini, &path, &path.with_extension("esmini.csv"), Duration::from_secs(60)) {
                        Err(e) => o.note = Some(e),
                        Ok(reference) => {
                            let c = compare::compare(&reference, &ours);
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

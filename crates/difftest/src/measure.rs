//! The long measurement (not in `cargo test`: 1,000 scenarios a run take minutes): several
//! seeds, each without and with a folder of maps, against esmini; one report per run, the
//! tally by feature over all of them, and each coverage element's agreement for
//! `measured.tsv`. Also the generator sample the coverage table's "generated" column is read
//! from.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use crate::compare::Verdict;
use crate::coverage::{elements_in, Measured};
use crate::generate::{generate, maps::MapChoice};
use crate::report::{Outcome, Report};
use crate::Plan;

/// Seed and scenario count of the generator sample behind the coverage table.
pub const SAMPLE_SEED: u64 = 1;
pub const SAMPLE_COUNT: u64 = 4000;

/// The coverage elements the generator emits over `count` scenarios of `seed` on `maps`.
pub fn generated_elements(seed: u64, count: u64, maps: &[MapChoice]) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for i in 0..count {
        out.extend(elements_in(&generate(seed, i, maps).xosc));
    }
    out
}

/// Each element's agreement over compared outcomes.
pub fn measured(outcomes: &[Outcome]) -> BTreeMap<String, Measured> {
    let mut out: BTreeMap<String, Measured> = BTreeMap::new();
    for o in outcomes {
        let Some(v) = o.verdict else { continue };
        for e in &o.elements {
            let m = out.entry(e.clone()).or_default();
            m.scenarios += 1;
            if v != Verdict::Diverged {
                m.agreed += 1;
            }
        }
    }
    out
}

/// One run of a measurement: its label and plan.
pub fn runs(seeds: &[u64], count: u64, out: &Path, esmini: &Path, maps: Option<&Path>, osc2cr: Option<&Path>) -> Vec<(String, Plan)> {
    let mut plans = Vec::new();
    for &seed in seeds {
        let folders: Vec<Option<&Path>> = if maps.is_some() { vec![None, maps] } else { vec![None] };
        for folder in folders {
            let label = match folder {
                None => format!("seed {seed}"),
                Some(_) => format!("seed {seed} --maps"),
            };
            let dir: PathBuf = out.join(label.replace(' ', "_").replace("--", ""));
            plans.push((
                label,
                Plan {
                    seed,
                    count,
                    out: dir,
                    esmini: Some(esmini.to_path_buf()),
                    maps: folder.map(Path::to_path_buf),
                    max_maps: 1000,
                    osc2cr: osc2cr.map(Path::to_path_buf),
                },
            ));
        }
    }
    plans
}

/// The reports of a measurement: one per run, then all runs together.
pub fn combined(reports: &[(String, Report)]) -> Report {
    let outcomes: Vec<Outcome> = reports.iter().flat_map(|(_, r)| r.scenarios.iter().cloned()).collect();
    Report::new(0, outcomes)
}

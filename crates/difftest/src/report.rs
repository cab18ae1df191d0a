//! Agreement by feature: for every feature, how many scenarios use it, and how many of those
//! agree exactly, closely or not at all — with the smallest scenario that shows a divergence.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::Serialize;

use crate::compare::Verdict;

/// One scenario's outcome.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    pub name: String,
    pub features: Vec<String>,
    /// None: not compared (no esmini, or esmini or osc2cr could not run it — see `note`).
    pub verdict: Option<Verdict>,
    pub max_pos_err: Option<f64>,
    pub ref_end: Option<f64>,
    pub our_end: Option<f64>,
    pub note: Option<String>,
    /// The coverage elements the scenario holds (`coverage::elements_in`).
    pub elements: Vec<String>,
    /// esmini's log lines marked `[error]` (a well-formed scenario has none).
    pub esmini_errors: Vec<String>,
    /// osc2cr's warnings on the scenario (reader and engine).
    pub osc2cr_warnings: Vec<String>,
    /// Size of the scenario file, bytes (the smallest divergence is the easiest to read).
    pub size: usize,
}

#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Tally {
    pub scenarios: usize,
    pub exact: usize,
    pub close: usize,
    pub diverged: usize,
    pub not_compared: usize,
    /// The smallest scenario of this feature that diverged.
    pub smallest_divergence: Option<String>,
    #[serde(skip)]
    smallest_size: usize,
}

impl Tally {
    fn add(&mut self, o: &Outcome) {
        self.scenarios += 1;
        match o.verdict {
            Some(Verdict::Exact) => self.exact += 1,
            Some(Verdict::Close) => self.close += 1,
            Some(Verdict::Diverged) => {
                self.diverged += 1;
                if self.smallest_divergence.is_none() || o.size < self.smallest_size {
                    self.smallest_divergence = Some(o.name.clone());
                    self.smallest_size = o.size;
                }
            }
            None => self.not_compared += 1,
        }
    }

    /// Exact-or-close among the compared scenarios.
    pub fn agreement(&self) -> Option<f64> {
        let compared = self.exact + self.close + self.diverged;
        (compared > 0).then(|| (self.exact + self.close) as f64 / compared as f64)
    }
}

#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Report {
    pub seed: u64,
    pub total: Tally,
    pub by_feature: BTreeMap<String, Tally>,
    pub scenarios: Vec<Outcome>,
}

impl Report {
    pub fn new(seed: u64, outcomes: Vec<Outcome>) -> Self {
        let mut r = Report { seed, ..Default::default() };
        for o in &outcomes {
            r.total.add(o);
            for f in &o.features {
                r.by_feature.entry(f.clone()).or_default().add(o);
            }
        }
        r.scenarios = outcomes;
        r
    }

    /// The table printed at the end of a run, its last line titled `title`.
    pub fn table(&self, title: &str) -> String {
        let mut out = String::new();
        let pct = |t: &Tally| t.agreement().map_or("-".to_string(), |a| format!("{:.1} %", 100.0 * a));
        let _ = writeln!(out, "{:<48} {:>5} {:>5} {:>5} {:>5} {:>5} {:>8}  smallest divergence", "feature", "n", "exact", "close", "div", "n/c", "agree");
        for (f, t) in &self.by_feature {
            let _ = writeln!(
                out,
                "{f:<48} {:>5} {:>5} {:>5} {:>5} {:>5} {:>8}  {}",
                t.scenarios,
                t.exact,
                t.close,
                t.diverged,
                t.not_compared,
                pct(t),
                t.smallest_divergence.as_deref().unwrap_or("")
            );
        }
        let t = &self.total;
        let _ = writeln!(out, "{:<48} {:>5} {:>5} {:>5} {:>5} {:>5} {:>8}", title, t.scenarios, t.exact, t.close, t.diverged, t.not_compared, pct(t));
        out
    }
}

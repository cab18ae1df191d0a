//! Comparing two runs as `../shared/tools/conformance.py` does: for every state of the
//! reference, our state at that time (linear interpolation), the largest position error over
//! every entity, and the end times. Exact: ≤ 0.10 m and ≤ 0.1 s; close: ≤ 1.0 m and ≤ 0.5 s.

use std::collections::BTreeMap;

use serde::Serialize;

pub const EXACT_POS: f64 = 0.10;
pub const EXACT_END: f64 = 0.1;
pub const CLOSE_POS: f64 = 1.0;
pub const CLOSE_END: f64 = 0.5;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    pub t: f64,
    pub x: f64,
    pub y: f64,
    pub h: f64,
    pub v: f64,
}

/// States per entity name, in time order. A log that goes back in time (esmini rewinds its
/// clock when a ghost restarts) is a replay: each stretch after a rewind is an entity of its
/// own, `NAME#2`, `NAME#3`, … as `conformance.py` reads it.
pub type Traces = BTreeMap<String, Vec<State>>;

/// Builds [`Traces`] from rows in log order, splitting an entity's rows where time goes back.
#[derive(Debug, Default)]
pub struct TraceBuilder {
    traces: Traces,
    /// Per entity: the time of its last row and its current stretch number.
    last: BTreeMap<String, (f64, u32)>,
}

impl TraceBuilder {
    pub fn push(&mut self, name: &str, s: State) {
        let stretch = match self.last.get(name) {
            Some(&(t, k)) if s.t < t - 1e-9 => k + 1,
            Some(&(_, k)) => k,
            None => 1,
        };
        self.last.insert(name.to_string(), (s.t, stretch));
        let key = if stretch == 1 { name.to_string() } else { format!("{name}#{stretch}") };
        self.traces.entry(key).or_default().push(s);
    }

    pub fn finish(mut self) -> Traces {
        for states in self.traces.values_mut() {
            states.sort_by(|a, b| a.t.total_cmp(&b.t));
        }
        self.traces
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    Exact,
    Close,
    Diverged,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    pub verdict: Verdict,
    /// Largest position error, m (None: an entity of the reference is missing from ours).
    pub max_pos_err: Option<f64>,
    /// The entity and time of the largest error.
    pub worst: Option<(String, f64)>,
    pub ref_end: f64,
    pub our_end: f64,
}

fn at(states: &[State], t: f64) -> Option<(f64, f64)> {
    let first = states.first()?;
    let last = states.last()?;
    if t < first.t - 1e-6 || t > last.t + 1e-6 {
        return None;
    }
    let i = states.partition_point(|s| s.t < t - 1e-9);
    if let Some(s) = states.get(i) {
        if (s.t - t).abs() < 1e-6 {
            return Some((s.x, s.y));
        }
    }
    let (a, b) = (states.get(i.checked_sub(1)?)?, states.get(i)?);
    let w = if b.t > a.t { (t - a.t) / (b.t - a.t) } else { 0.0 };
    Some((a.x + w * (b.x - a.x), a.y + w * (b.y - a.y)))
}

/// `ours` against `reference`.
pub fn compare(reference: &Traces, ours: &Traces) -> Comparison {
    let end = |t: &Traces| t.values().filter_map(|s| s.last().map(|s| s.t)).fold(0.0, f64::max);
    let (ref_end, our_end) = (end(reference), end(ours));
    let mut worst: Option<(f64, String, f64)> = None;
    let mut missing = false;
    let mut covered_all = true;
    for (name, rs) in reference {
        let Some(os) = ours.get(name).filter(|s| !s.is_empty()) else {
            missing = true;
            continue;
        };
        let mut covered = 0usize;
        for r in rs {
            let Some((x, y)) = at(os, r.t) else { continue };
            covered += 1;
            let e = (x - r.x).hypot(y - r.y);
            if worst.as_ref().is_none_or(|w| e > w.0) {
                worst = Some((e, name.clone(), r.t));
            }
        }
        if (covered as f64) < 0.99 * rs.len() as f64 {
            covered_all = false;
        }
    }
    let max_pos_err = if missing { None } else { Some(worst.as_ref().map_or(0.0, |w| w.0)) };
    let dend = (ref_end - our_end).abs();
    let verdict = match max_pos_err {
        Some(e) if covered_all && e <= EXACT_POS && dend <= EXACT_END => Verdict::Exact,
        Some(e) if covered_all && e <= CLOSE_POS && dend <= CLOSE_END => Verdict::Close,
        _ => Verdict::Diverged,
    };
    Comparison { verdict, max_pos_err, worst: worst.map(|w| (w.1, w.2)), ref_end, our_end }
}

//! Parameter value distributions: the runs a ParameterValueDistribution file describes, as a
//! lazy sequence of concrete parameter sets whose number is known up front.
//!
//! Deterministic: the runs are the cross product of every distribution (each
//! DeterministicSingleParameterDistribution and each DeterministicMultiParameterDistribution is
//! one factor), in odometer order — the last factor varies fastest. Run `i` is computed from
//! `i` alone, so nothing is materialised.
//!
//! Stochastic: `numberOfTestRuns` runs; run `i` draws every parameter, in file order, from a
//! ChaCha20 generator seeded with the seed and set to stream `i` (portable and random-access).

mod read;
mod sample;

pub(crate) use read::read_distribution;

use serde::Serialize;
use std::path::PathBuf;

/// One run's parameter values, as (name, value) pairs to use as overrides.
pub type ParameterSet = Vec<(String, String)>;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Distribution {
    /// The scenario the distribution varies (absolute path).
    pub scenario_file: PathBuf,
    pub kind: DistributionKind,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum DistributionKind {
    Deterministic(Vec<Factor>),
    Stochastic { runs: u64, seed: u64, parameters: Vec<(String, Stochastic)> },
}

/// One factor of a deterministic cross product.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Factor {
    /// DistributionSet: the listed values.
    Set { parameter: String, values: Vec<String> },
    /// DistributionRange: lower, lower + step, ... up to upper (inclusive, within 1e-9 steps).
    Range { parameter: String, lower: f64, step: f64, count: u64 },
    /// ValueSetDistribution: each set assigns several parameters at once.
    ValueSets(Vec<ParameterSet>),
}

impl Factor {
    fn len(&self) -> u64 {
        match self {
            Factor::Set { values, .. } => values.len() as u64,
            Factor::Range { count, .. } => *count,
            Factor::ValueSets(sets) => sets.len() as u64,
        }
    }

    fn push(&self, i: u64, out: &mut ParameterSet) {
        match self {
            Factor::Set { parameter, values } => {
                if let Some(v) = usize::try_from(i).ok().and_then(|i| values.get(i)) {
                    out.push((parameter.clone(), v.clone()));
                }
            }
            Factor::Range { parameter, lower, step, .. } => {
                out.push((parameter.clone(), format_number(lower + step * i as f64)));
            }
            Factor::ValueSets(sets) => {
                if let Some(s) = usize::try_from(i).ok().and_then(|i| sets.get(i)) {
                    out.extend(s.iter().cloned());
                }
            }
        }
    }
}

/// A stochastic distribution of one parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Stochastic {
    /// Normal with `expected_value` and `variance`, truncated to `range` by redrawing.
    Normal {
        expected_value: f64,
        variance: f64,
        range: Option<(f64, f64)>,
    },
    /// Log-normal whose underlying normal has mean `expected_value` and `variance`.
    LogNormal {
        expected_value: f64,
        variance: f64,
        range: Option<(f64, f64)>,
    },
    Uniform {
        lower: f64,
        upper: f64,
    },
    Poisson {
        expected_value: f64,
        range: Option<(f64, f64)>,
    },
    /// Bins (weight, lower, upper): a bin by weight, then uniform inside it.
    Histogram(Vec<(f64, f64, f64)>),
    /// ProbabilityDistributionSet: (value, weight).
    Set(Vec<(String, f64)>),
}

impl Distribution {
    /// Number of runs (saturating at u64::MAX; the reader rejects products that overflow).
    pub fn len(&self) -> u64 {
        match &self.kind {
            DistributionKind::Deterministic(f) => f.iter().try_fold(1u64, |acc, x| acc.checked_mul(x.len())).unwrap_or(u64::MAX),
            DistributionKind::Stochastic { runs, .. } => *runs,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The parameter values of run `index` (None past the end).
    pub fn get(&self, index: u64) -> Option<ParameterSet> {
        if index >= self.len() {
            return None;
        }
        match &self.kind {
            DistributionKind::Deterministic(factors) => {
                let mut out = Vec::new();
                let mut rest = index;
                let mut digits = vec![0u64; factors.len()];
                for (d, f) in factors.iter().enumerate().rev() {
                    let n = f.len().max(1);
                    digits[d] = rest % n;
                    rest /= n;
                }
                for (f, i) in factors.iter().zip(digits) {
                    f.push(i, &mut out);
                }
                Some(out)
            }
            DistributionKind::Stochastic { seed, parameters, .. } => Some(sample::draw_run(*seed, index, parameters)),
        }
    }

    /// Load options for run `index`: `base` with the run's values appended to its overrides
    /// (so a run's value wins over a command-line value for the same parameter).
    pub fn run_options(&self, index: u64, base: &crate::LoadOptions) -> Option<crate::LoadOptions> {
        let set = self.get(index)?;
        let mut options = base.clone();
        options.parameters.retain(|(n, _)| !set.iter().any(|(m, _)| m == n));
        options.parameters.extend(set);
        Some(options)
    }

    /// Every run, lazily, in order.
    pub fn iter(&self) -> ParameterSets<'_> {
        ParameterSets { dist: self, next: 0, len: self.len() }
    }
}

/// Lazy iterator over the runs of a distribution.
pub struct ParameterSets<'a> {
    dist: &'a Distribution,
    next: u64,
    len: u64,
}

impl Iterator for ParameterSets<'_> {
    type Item = ParameterSet;
    fn next(&mut self) -> Option<ParameterSet> {
        if self.next >= self.len {
            return None;
        }
        let v = self.dist.get(self.next);
        self.next += 1;
        v
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        let rest = usize::try_from(self.len - self.next).unwrap_or(usize::MAX);
        (rest, Some(rest))
    }
}

/// Numbers as short text: rounded to 1e-9 so that 1.1 + 0.2 prints as 1.3.
pub(crate) fn format_number(v: f64) -> String {
    let r = (v * 1e9).round() / 1e9;
    if r == 0.0 {
        return "0".to_string();
    }
    format!("{r}")
}

//! Reading a ParameterValueDistribution element.

use super::{Distribution, DistributionKind, Factor, ParameterSet, Stochastic};
use crate::attr::{Cx, Record};
use crate::error::{Diagnostic, Error, ErrorKind};
use crate::params::Scope;
use crate::xml::Elem;
use std::path::Path;
use std::sync::Arc;

/// Largest number of values one DistributionRange may produce.
const MAX_RANGE_VALUES: u64 = 1 << 40;

pub(crate) fn read_distribution(
    warnings: &mut Vec<Diagnostic>,
    problems: &mut Vec<Diagnostic>,
    path: &Path,
    file: &Arc<Path>,
    root: &Elem,
    d: &Elem,
    seed_override: Option<u64>,
) -> Result<Distribution, Error> {
    let scope = Scope::default();
    let record = Record::default();
    let cx = Cx::new(file.clone(), &scope, &record);
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let sf = cx.child(d, "ScenarioFile")?;
    let scenario_file = crate::error::absolute(&dir.join(cx.text(sf, "filepath")?));
    if !scenario_file.is_file() {
        warnings.push(Diagnostic { location: cx.loc(sf.pos), message: format!("scenario file {} not found", scenario_file.display()) });
    }
    let _ = root;
    let kind = if let Some(det) = d.child("Deterministic") {
        let mut factors = Vec::new();
        for f in det.children() {
            match f.name.as_str() {
                "DeterministicMultiParameterDistribution" => {
                    let vsd = cx.child(f, "ValueSetDistribution")?;
                    let mut sets = Vec::new();
                    for s in vsd.children_named("ParameterValueSet") {
                        let mut set: ParameterSet = Vec::new();
                        for a in s.children_named("ParameterAssignment") {
                            set.push((cx.name_ref(a, "parameterRef")?, cx.text(a, "value")?));
                        }
                        sets.push(set);
                    }
                    if sets.is_empty() {
                        problems.push(Diagnostic {
                            location: cx.loc(vsd.pos),
                            message: "ValueSetDistribution has no ParameterValueSet: the distribution has no run".into(),
                        });
                    }
                    factors.push(Factor::ValueSets(sets));
                }
                "DeterministicSingleParameterDistribution" => factors.push(single(warnings, problems, &cx, f)?),
                _ => warnings.push(Diagnostic { location: cx.loc(f.pos), message: format!("<{}> in Deterministic is not supported yet; ignored", f.name) }),
            }
        }
        let dist = DistributionKind::Deterministic(factors);
        let probe = Distribution { scenario_file: scenario_file.clone(), kind: dist };
        let total = match &probe.kind {
            DistributionKind::Deterministic(f) => f.iter().try_fold(1u64, |acc, x| acc.checked_mul(x.len())),
            DistributionKind::Stochastic { runs, .. } => Some(*runs),
        };
        if total.is_none() {
            return Err(cx.err(ErrorKind::Limit, det.pos, "the number of runs does not fit in 64 bits"));
        }
        probe.kind
    } else if let Some(st) = d.child("Stochastic") {
        let runs = u64::from(cx.u32_or(st, "numberOfTestRuns", 0)?);
        let file_seed = cx.opt_f64(st, "randomSeed")?.map(|s| s as u64).unwrap_or(0);
        let mut parameters = Vec::new();
        for s in st.children_named("StochasticDistribution") {
            let name = cx.name_ref(s, "parameterName")?;
            let c = cx.choice(s, "a stochastic distribution type")?;
            let range = |e: &Elem| -> Result<Option<(f64, f64)>, Error> {
                e.child("Range").map(|r| Ok((cx.f64(r, "lowerLimit")?, cx.f64(r, "upperLimit")?))).transpose()
            };
            let dist = match c.name.as_str() {
                "NormalDistribution" => Stochastic::Normal { expected_value: cx.f64(c, "expectedValue")?, variance: cx.f64(c, "variance")?, range: range(c)? },
                "LogNormalDistribution" => {
                    Stochastic::LogNormal { expected_value: cx.f64(c, "expectedValue")?, variance: cx.f64(c, "variance")?, range: range(c)? }
                }
                "UniformDistribution" => {
                    let r = cx.child(c, "Range")?;
                    Stochastic::Uniform { lower: cx.f64(r, "lowerLimit")?, upper: cx.f64(r, "upperLimit")? }
                }
                "PoissonDistribution" => Stochastic::Poisson { expected_value: cx.f64(c, "expectedValue")?, range: range(c)? },
                "Histogram" => Stochastic::Histogram(
                    c.children_named("Bin")
                        .map(|b| {
                            let r = cx.child(b, "Range")?;
                            Ok((cx.f64(b, "weight")?, cx.f64(r, "lowerLimit")?, cx.f64(r, "upperLimit")?))
                        })
                        .collect::<Result<_, Error>>()?,
                ),
                "ProbabilityDistributionSet" => {
                    Stochastic::Set(c.children_named("Element").map(|e| Ok((cx.text(e, "value")?, cx.f64(e, "weight")?))).collect::<Result<_, Error>>()?)
                }
                _ => {
                    warnings.push(Diagnostic {
                        location: cx.loc(c.pos),
                        message: format!("<{}> is not supported yet; parameter '{name}' keeps its scenario value", c.name),
                    });
                    continue;
                }
            };
            if let Some(why) = unsampleable(&dist) {
                problems.push(Diagnostic { location: cx.loc(c.pos), message: format!("<{}> of parameter '{name}' cannot be sampled: {why}", c.name) });
            }
            parameters.push((name, dist));
        }
        DistributionKind::Stochastic { runs, seed: seed_override.unwrap_or(file_seed), parameters }
    } else {
        return Err(cx.err(ErrorKind::Structure, d.pos, "ParameterValueDistribution needs a Deterministic or Stochastic child"));
    };
    problems.append(&mut record.problems.take());
    Ok(Distribution { scenario_file, kind })
}

fn single(warnings: &mut Vec<Diagnostic>, problems: &mut Vec<Diagnostic>, cx: &Cx, f: &Elem) -> Result<Factor, Error> {
    let parameter = cx.name_ref(f, "parameterName")?;
    let c = cx.choice(f, "DistributionSet, DistributionRange or UserDefinedDistribution")?;
    match c.name.as_str() {
        "DistributionSet" => {
            let values: Vec<String> = c.children_named("Element").map(|e| cx.text(e, "value")).collect::<Result<_, _>>()?;
            if values.is_empty() {
                problems.push(Diagnostic {
                    location: cx.loc(c.pos),
                    message: format!("DistributionSet of parameter '{parameter}' has no Element: the distribution has no run"),
                });
            }
            Ok(Factor::Set { parameter, values })
        }
        "DistributionRange" => {
            let step = cx.f64(c, "stepWidth")?;
            let r = cx.child(c, "Range")?;
            let lower = cx.f64(r, "lowerLimit")?;
            let upper = cx.f64(r, "upperLimit")?;
            if step.is_nan() || step <= 0.0 || !step.is_finite() || !lower.is_finite() || !upper.is_finite() {
                return Err(cx.err(ErrorKind::Value, c.pos, format!("stepWidth must be a positive number, found {step}")));
            }
            // Inclusive of `upper` up to rounding: (1.5 - 1.1) / 0.2 is 2.0000000000000004.
            let steps = ((upper - lower) / step + 1e-9).floor();
            let count = if steps < 0.0 { 0 } else { steps as u64 + 1 };
            if upper < lower {
                problems.push(Diagnostic {
                    location: cx.loc(r.pos),
                    message: format!("DistributionRange of parameter '{parameter}': upperLimit {upper} is below lowerLimit {lower}, so the range is empty"),
                });
            }
            if count > MAX_RANGE_VALUES {
                return Err(cx.err(ErrorKind::Limit, c.pos, format!("range gives {count} values, more than {MAX_RANGE_VALUES}")));
            }
            Ok(Factor::Range { parameter, lower, step, count })
        }
        _ => {
            warnings.push(Diagnostic {
                location: cx.loc(c.pos),
                message: format!("<{}> is not supported yet; parameter '{parameter}' keeps its scenario value", c.name),
            });
            Ok(Factor::ValueSets(vec![Vec::new()]))
        }
    }
}

/// Why a stochastic distribution cannot be sampled as written, if it cannot: a negative
/// variance, an inverted or empty range, weights that are negative or (for a
/// ProbabilityDistributionSet) do not sum to a positive number.
// `!(v >= 0.0)` is meant: it holds for NaN too, which cannot be sampled either.
#[allow(clippy::neg_cmp_op_on_partial_ord)]
fn unsampleable(d: &Stochastic) -> Option<String> {
    let inverted = |r: &Option<(f64, f64)>| match r {
        Some((lo, hi)) if hi < lo => Some(format!("its Range is inverted (upperLimit {hi} < lowerLimit {lo})")),
        _ => None,
    };
    match d {
        Stochastic::Normal { variance, range, .. } | Stochastic::LogNormal { variance, range, .. } => {
            if !(*variance >= 0.0) {
                return Some(format!("variance {variance} is negative"));
            }
            inverted(range)
        }
        Stochastic::Uniform { lower, upper } if !(upper > lower) => Some(format!("its Range is empty or inverted (lowerLimit {lower}, upperLimit {upper})")),
        Stochastic::Uniform { .. } => None,
        Stochastic::Poisson { expected_value, range } => {
            if !(*expected_value > 0.0) {
                return Some(format!("expectedValue {expected_value} is not positive"));
            }
            inverted(range)
        }
        Stochastic::Histogram(bins) => {
            if bins.is_empty() {
                return Some("it has no Bin".into());
            }
            if let Some((w, lo, hi)) = bins.iter().find(|(w, lo, hi)| !(*w >= 0.0) || !(hi > lo)) {
                return Some(format!("a Bin has weight {w} and range {lo}..{hi} (weights must not be negative, ranges not empty)"));
            }
            None
        }
        Stochastic::Set(items) => {
            if items.is_empty() {
                return Some("it has no Element".into());
            }
            if let Some((v, w)) = items.iter().find(|(_, w)| !(*w >= 0.0)) {
                return Some(format!("element '{v}' has negative weight {w}"));
            }
            // Weights are relative: the ASAM example SlowPrecedingVehicleStochasticParameterSet
            // weighs its values 5, 10, 20, and samplers normalise by the sum; only a sum that is
            // not positive leaves nothing to draw from.
            let sum: f64 = items.iter().map(|(_, w)| w).sum();
            if !(sum > 0.0 && sum.is_finite()) {
                return Some(format!("its weights sum to {sum}; they must sum to a positive number"));
            }
            None
        }
    }
}

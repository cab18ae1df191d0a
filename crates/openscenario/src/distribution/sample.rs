//! Drawing one stochastic run.

use super::{format_number, ParameterSet, Stochastic};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha20Rng;
use rand_distr::{Distribution as _, LogNormal, Normal, Poisson};

/// Redraws allowed to land inside a truncation range before clamping.
const MAX_REDRAWS: usize = 1000;

pub(super) fn draw_run(seed: u64, run: u64, parameters: &[(String, Stochastic)]) -> ParameterSet {
    let mut rng = ChaCha20Rng::seed_from_u64(seed);
    rng.set_stream(run);
    parameters.iter().map(|(name, d)| (name.clone(), draw(&mut rng, d))).collect()
}

fn truncated(rng: &mut ChaCha20Rng, range: Option<(f64, f64)>, mut f: impl FnMut(&mut ChaCha20Rng) -> f64) -> f64 {
    let Some((lo, hi)) = range else { return f(rng) };
    for _ in 0..MAX_REDRAWS {
        let v = f(rng);
        if (lo..=hi).contains(&v) {
            return v;
        }
    }
    f(rng).clamp(lo.min(hi), hi.max(lo))
}

fn pick<'a, T>(rng: &mut ChaCha20Rng, items: &'a [T], weight: impl Fn(&T) -> f64) -> Option<&'a T> {
    let total: f64 = items.iter().map(|i| weight(i).max(0.0)).sum();
    if items.is_empty() {
        return None;
    }
    if total <= 0.0 || !total.is_finite() {
        return items.first();
    }
    let mut x = rng.gen::<f64>() * total;
    for it in items {
        x -= weight(it).max(0.0);
        if x < 0.0 {
            return Some(it);
        }
    }
    items.last()
}

fn draw(rng: &mut ChaCha20Rng, d: &Stochastic) -> String {
    match d {
        Stochastic::Normal { expected_value, variance, range } => {
            let n = Normal::new(*expected_value, variance.max(0.0).sqrt()).ok();
            format_number(truncated(rng, *range, |r| n.map_or(*expected_value, |n| n.sample(r))))
        }
        Stochastic::LogNormal { expected_value, variance, range } => {
            let n = LogNormal::new(*expected_value, variance.max(0.0).sqrt()).ok();
            format_number(truncated(rng, *range, |r| n.map_or(expected_value.exp(), |n| n.sample(r))))
        }
        Stochastic::Uniform { lower, upper } => {
            let (lo, hi) = (lower.min(*upper), lower.max(*upper));
            format_number(if hi > lo { rng.gen_range(lo..hi) } else { lo })
        }
        Stochastic::Poisson { expected_value, range } => {
            let p = Poisson::new(*expected_value).ok();
            format_number(truncated(rng, *range, |r| p.map_or(0.0, |p| p.sample(r))))
        }
        Stochastic::Histogram(bins) => match pick(rng, bins, |b| b.0) {
            Some(&(_, lo, hi)) if hi > lo => format_number(rng.gen_range(lo..hi)),
            Some(&(_, lo, _)) => format_number(lo),
            None => String::new(),
        },
        Stochastic::Set(items) => pick(rng, items, |i| i.1).map(|i| i.0.clone()).unwrap_or_default(),
    }
}

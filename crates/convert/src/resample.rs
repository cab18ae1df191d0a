//! From the engine's step (0.01 s) to CommonRoad's time step (0.1 s). When the CommonRoad step
//! is a whole multiple of the engine step every k-th sample is taken as it is (no smoothing,
//! no drift); otherwise the two neighbouring samples are interpolated linearly, the heading
//! along the shorter arc.

use crate::angle::{lerp_angle, wrap_angle};
use engine::Sample;

/// An entity's reference-point state at one CommonRoad time step (heading wrapped).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub h: f64,
    pub speed: f64,
    pub acceleration: f64,
    pub yaw_rate: f64,
}

impl Pose {
    fn of(s: &Sample) -> Self {
        Self { x: s.x, y: s.y, h: wrap_angle(s.h), speed: s.speed, acceleration: s.acceleration, yaw_rate: s.yaw_rate }
    }

    fn lerp(a: &Sample, b: &Sample, f: f64) -> Self {
        let l = |p: f64, q: f64| p + f * (q - p);
        Self {
            x: l(a.x, b.x),
            y: l(a.y, b.y),
            h: lerp_angle(a.h, b.h, f),
            speed: l(a.speed, b.speed),
            acceleration: l(a.acceleration, b.acceleration),
            yaw_rate: l(a.yaw_rate, b.yaw_rate),
        }
    }
}

/// Relative tolerance for "is a whole multiple" and "falls on a sample".
const EPS: f64 = 1e-9;

/// How many CommonRoad steps a trace of `len` engine steps covers: every `n` with
/// `n·dt <= (len−1)·step`. Zero for an empty trace or a non-positive step.
pub fn cr_step_count(len: usize, step: f64, dt: f64) -> usize {
    if len == 0 || !(step > 0.0 && dt > 0.0 && step.is_finite() && dt.is_finite()) {
        return 0;
    }
    let last = (len - 1) as f64 * step;
    let n = (last / dt + EPS).floor();
    // n is finite and >= 0 here; `as` saturates for absurd ratios and the caller caps dt
    n as usize + 1
}

/// The engine step `k` when `dt` is a whole multiple `k·step`.
pub fn whole_multiple(step: f64, dt: f64) -> Option<usize> {
    let ratio = dt / step;
    let k = ratio.round();
    (k >= 1.0 && (ratio - k).abs() <= EPS * ratio.max(1.0)).then_some(k as usize)
}

/// The entity's state at every CommonRoad step (`None` where it does not exist).
pub fn resample(samples: &[Option<Sample>], step: f64, dt: f64) -> Vec<Option<Pose>> {
    let n = cr_step_count(samples.len(), step, dt);
    let at = |i: usize| samples.get(i).copied().flatten();
    if let Some(k) = whole_multiple(step, dt) {
        return (0..n).map(|i| at(i.saturating_mul(k)).map(|s| Pose::of(&s))).collect();
    }
    (0..n)
        .map(|i| {
            let f = i as f64 * dt / step;
            let i0 = f.floor();
            let frac = f - i0;
            let i0 = i0 as usize;
            if frac <= EPS {
                return at(i0).map(|s| Pose::of(&s));
            }
            if 1.0 - frac <= EPS {
                return at(i0 + 1).map(|s| Pose::of(&s));
            }
            // between two samples: the entity must exist at both
            match (at(i0), at(i0 + 1)) {
                (Some(a), Some(b)) => Some(Pose::lerp(&a, &b, frac)),
                _ => None,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn sample(t: f64) -> Sample {
        // x = 3t + t², speed = 3 + 2t: a closed form to check interpolation against
        Sample { x: 3.0 * t + t * t, y: -2.0, z: 0.0, h: 0.1 * t, speed: 3.0 + 2.0 * t, acceleration: 2.0, yaw_rate: 0.1, road: None, visible: true }
    }

    /// The engine's step of the traces here, s.
    const STEP: f64 = 0.01;

    /// [`sample`] at steps 0 to `last` of [`STEP`].
    fn samples(last: u32) -> Vec<Option<Sample>> {
        (0..=last).map(|i| Some(sample(f64::from(i) * STEP))).collect()
    }

    #[test]
    fn counts_steps_covered_by_the_trace() {
        assert_eq!(cr_step_count(0, 0.01, 0.1), 0);
        assert_eq!(cr_step_count(1, 0.01, 0.1), 1);
        assert_eq!(cr_step_count(1001, 0.01, 0.1), 101); // 10 s
        assert_eq!(cr_step_count(1000, 0.01, 0.1), 100); // 9.99 s
        assert_eq!(cr_step_count(10, 0.01, 0.0), 0);
    }

    #[test]
    fn whole_multiple_takes_every_kth_sample() {
        let out = resample(&samples(250), STEP, 0.1);
        assert_eq!(out.len(), 26);
        for (n, p) in out.iter().enumerate() {
            let p = p.expect("present");
            let t = n as f64 * 0.1;
            assert!((p.x - (3.0 * t + t * t)).abs() < 1e-9, "step {n}");
            assert!((p.speed - (3.0 + 2.0 * t)).abs() < 1e-9);
        }
    }

    #[test]
    fn other_ratios_interpolate() {
        // dt = 0.025 s over a 0.01 s trace: t = 0.025 lies halfway between 0.02 and 0.03
        let out = resample(&samples(100), STEP, 0.025);
        assert_eq!(out.len(), 41);
        let p = out[1].expect("present");
        let lin = |a: f64, b: f64| 0.5 * (a + b);
        let (a, b) = (sample(0.02), sample(0.03));
        assert!((p.x - lin(a.x, b.x)).abs() < 1e-12);
        assert!((p.speed - (3.0 + 2.0 * 0.025)).abs() < 1e-12); // linear quantity: exact
        assert!((p.h - 0.0025).abs() < 1e-12);
        // t = 0.05 falls on sample 5 exactly
        let p = out[2].expect("present");
        assert!((p.x - sample(0.05).x).abs() < 1e-12);
    }

    #[test]
    fn interpolated_heading_takes_the_short_way() {
        let mut a = sample(0.0);
        let mut b = sample(0.01);
        a.h = PI - 0.01;
        b.h = -PI + 0.01;
        let out = resample(&[Some(a), Some(b)], 0.01, 0.005);
        let p = out[1].expect("present");
        assert!((p.h.abs() - PI).abs() < 1e-9, "{}", p.h);
    }

    #[test]
    fn headings_are_wrapped() {
        let mut s = sample(0.0);
        s.h = 2.0 * PI + 0.5;
        let out = resample(&[Some(s)], 0.01, 0.1);
        assert!((out[0].expect("present").h - 0.5).abs() < 1e-12);
    }

    #[test]
    fn absence_is_kept_and_interpolation_needs_both_neighbours() {
        let step = 0.01;
        let samples: Vec<_> = (0..=30).map(|i| (i >= 12).then(|| sample(i as f64 * step))).collect();
        let out = resample(&samples, step, 0.1);
        assert_eq!(out.len(), 4);
        assert!(out[0].is_none() && out[1].is_none());
        assert!(out[2].is_some() && out[3].is_some());
        // interpolated: t = 0.115 needs samples 11 (absent) and 12
        let out = resample(&samples, step, 0.115);
        assert!(out[1].is_none());
    }
}

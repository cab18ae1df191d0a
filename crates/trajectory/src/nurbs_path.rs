//! A NURBS curve made walkable the way esmini does it: sampled uniformly in its parameter
//! with about one sample per metre of control polygon; arc length is the length of that
//! polyline, a position is the exact curve point at the parameter interpolated linearly
//! between two samples, and the heading is interpolated between the samples' headings.
//! Matching the coarse sampling matters: the times of the control points are spread over
//! the samples, so a finer sampling would move the entity differently in time.
//! When the first control point gives a heading, esmini takes every heading from the control
//! points' headings instead (NurbsShape::EvaluateInternal): see [`NurbsPath::blended_heading`].

use crate::angle;
use crate::error::Error;
use crate::nurbs::Nurbs;
use crate::pose::PathPoint;
use crate::ESMINI_SMALL;

/// Control-polygon length per sample (m), as esmini's NURBS_STEPLENGTH.
const STEP_LENGTH: f64 = 1.0;
/// Parameter offset used to find the tangent direction at a sample (esmini: 0.001 or less).
const TANGENT_DU: f64 = 0.001;
/// Points closer than this count as coincident (esmini's SMALL_NUMBER).
const SMALL: f64 = 1e-10;
const MAX_SAMPLES: usize = 200_000;

#[derive(Debug, Clone, PartialEq)]
pub(crate) struct NurbsPath {
    curve: Nurbs,
    /// (s, u, heading) at each sample; s non-decreasing.
    samples: Vec<(f64, f64, f64)>,
    /// Parameter where each sample's basis values were taken for the time rule (the tangent
    /// probe's parameter, as esmini reads the basis values left by its last evaluation).
    probe_u: Vec<f64>,
    /// Every control point's heading, when the first one gives its own (esmini then blends
    /// them instead of following the curve's direction).
    cp_headings: Option<Vec<f64>>,
}

impl NurbsPath {
    /// `cp_headings`: each control point's heading, to be blended when the first control point
    /// gives a heading of its own (None: headings follow the curve).
    pub(crate) fn new(curve: Nurbs, cp_headings: Option<Vec<f64>>) -> Result<NurbsPath, Error> {
        let pts = curve.control_points();
        let polygon: f64 = pts
            .windows(2)
            .map(|w| match w {
                [a, b] => (b[0] - a[0]).hypot(b[1] - a[1]),
                _ => 0.0,
            })
            .sum();
        if !polygon.is_finite() {
            return Err(Error::BadNumber { shape: "NURBS", what: "control polygon length".into(), constraint: "", value: polygon });
        }
        if polygon <= 0.0 {
            return Err(Error::ZeroLength { shape: "NURBS" });
        }
        let wanted = (1.0 + polygon / STEP_LENGTH).floor();
        let n = if wanted < MAX_SAMPLES as f64 { (wanted as usize).max(1) } else { MAX_SAMPLES };
        let (a, b) = curve.domain();
        // esmini walks the parameter from 0 to the last knot, evaluating clamped to the domain.
        let u_max = b;
        let du = u_max / n as f64;
        let probe = du.abs().min(TANGENT_DU);
        // NurbsShape::EvaluateInternal clamps t to the last knot less SMALL_NUMBER (1e-6).
        let at = |u: f64| curve.esmini_point(u.clamp(a, (b - ESMINI_SMALL).max(a)));
        let mut samples: Vec<(f64, f64, f64)> = Vec::with_capacity(n + 1);
        let mut probe_u = Vec::with_capacity(n + 1);
        let mut s = 0.0;
        let mut prev: Option<[f64; 3]> = None;
        let mut heading = f64::NAN;
        for i in 0..=n {
            let u = i as f64 * du;
            let p = at(u);
            let pu = if i < n { (u + probe).min(u_max) } else { (u - probe).max(0.0) };
            let q = at(pu);
            if let Some(o) = prev {
                s += (p[0] - o[0]).hypot(p[1] - o[1]);
            }
            if (q[0] - p[0]).hypot(q[1] - p[1]) > SMALL {
                heading = if i == 0 {
                    f64::NAN // taken from the next sample below
                } else if i < n {
                    angle::normalize((q[1] - p[1]).atan2(q[0] - p[0]))
                } else {
                    angle::normalize((p[1] - q[1]).atan2(p[0] - q[0]))
                };
            }
            // Coincident probe: the heading of the previous sample is kept.
            samples.push((s, u, heading));
            probe_u.push(pu);
            prev = Some(p);
        }
        if !(s.is_finite() && s > 0.0) {
            return Err(Error::ZeroLength { shape: "NURBS" });
        }
        // Missing headings (start, or a start on coincident points) come from the successor.
        if let Some(last) = samples.last_mut() {
            if last.2.is_nan() {
                last.2 = 0.0;
            }
        }
        for k in (0..samples.len().saturating_sub(1)).rev() {
            if samples[k].2.is_nan() {
                samples[k].2 = samples[k + 1].2;
            }
        }
        Ok(NurbsPath { curve, samples, probe_u, cp_headings })
    }

    pub(crate) fn length(&self) -> f64 {
        self.samples.last().map_or(0.0, |p| p.0)
    }

    pub(crate) fn eval(&self, s: f64) -> PathPoint {
        let sm = &self.samples;
        let i = sm.partition_point(|p| p.0 <= s).saturating_sub(1).min(sm.len().saturating_sub(2));
        let (Some(&(s0, u0, h0)), Some(&(s1, u1, h1))) = (sm.get(i), sm.get(i + 1)) else {
            return PathPoint { s, x: 0.0, y: 0.0, z: 0.0, heading: 0.0, curvature: 0.0 };
        };
        let ds = s1 - s0;
        let a = if ds > 0.0 { ((s - s0) / ds).clamp(0.0, 1.0) } else { 0.0 };
        let (lo, hi) = self.curve.domain();
        let u = (u0 + a * (u1 - u0)).clamp(lo, (hi - ESMINI_SMALL).max(lo));
        let p = self.curve.esmini_point(u);
        let turn = angle::diff(h1, h0);
        let heading = match &self.cp_headings {
            Some(hs) => self.blended_heading(hs, u),
            None => angle::normalize(h0 + a * turn),
        };
        PathPoint { s, x: p[0], y: p[1], z: p[2], heading, curvature: if ds > 0.0 { turn / ds } else { 0.0 } }
    }

    /// esmini's heading where the first control point gives one (NurbsShape::EvaluateInternal):
    /// starting from 0, each control point whose basis value at `u` counts pulls the heading
    /// towards its own by its share of the rational weight (the smallest angle), one after the
    /// other in order. A control point without a heading of its own brings the one its position
    /// has (esmini: the road's direction there).
    fn blended_heading(&self, hs: &[f64], u: f64) -> f64 {
        let pts = self.curve.control_points();
        let basis = self.curve.basis(u);
        let total: f64 = basis.iter().zip(pts).map(|(b, p)| b * p[3]).sum();
        if !(total.is_finite() && total > 0.0) {
            return 0.0;
        }
        let mut h = 0.0;
        for ((b, p), hi) in basis.iter().zip(pts).zip(hs) {
            if *b > ESMINI_SMALL {
                h += b * p[3] / total * angle::diff(*hi, h);
            }
        }
        angle::normalize(h)
    }

    /// (s, time) at every sample, esmini's rule: each control point's time belongs to the
    /// sample parameter where its basis function was largest; times between are linear in the
    /// parameter; the current control point advances at most one per sample.
    pub(crate) fn time_stamps(&self, times: &[f64]) -> Vec<(f64, f64)> {
        let n = self.curve.control_points().len();
        let mut peak_u = vec![0.0; n];
        let mut peak_v = vec![0.0; n];
        let (lo, hi) = self.curve.domain();
        for (&(_, u, _), &pu) in self.samples.iter().zip(&self.probe_u) {
            let (first, vals) = self.curve.basis_nonzero(pu.clamp(lo, (hi - SMALL).max(lo)));
            for (i, v) in vals.into_iter().enumerate().map(|(r, v)| (first + r, v)) {
                if let (Some(pv), Some(pk)) = (peak_v.get_mut(i), peak_u.get_mut(i)) {
                    if v > *pv {
                        *pv = v;
                        *pk = u;
                    }
                }
            }
        }
        let mut out = Vec::with_capacity(self.samples.len());
        let mut k = 0usize;
        for &(s, u, _) in &self.samples {
            if n >= 2 && peak_u.get(k + 1).is_some_and(|&p| u >= p) {
                k = (k + 1).min(n - 2);
            }
            let (Some(&ua), Some(&ub), Some(&ta), Some(&tb)) = (peak_u.get(k), peak_u.get(k + 1), times.get(k), times.get(k + 1)) else {
                out.push((s, times.first().copied().unwrap_or(0.0)));
                continue;
            };
            let w = if ub != ua { (u - ua) / (ub - ua) } else { 1.0 };
            out.push((s, ta + w * (tb - ta)));
        }
        out
    }
}

//! A NURBS curve made walkable: sampled uniformly in its parameter (as esmini does, but
//! finer) to map arc length → parameter; positions are then evaluated exactly at the
//! interpolated parameter and headings interpolated between samples.

use crate::angle;
use crate::error::TrajectoryError;
use crate::nurbs::Nurbs;
use crate::pose::PathPoint;

/// Target chord between samples (m) and the sample count bounds.
const SAMPLE_STEP: f64 = 0.1;
const MIN_SAMPLES_PER_POINT: usize = 16;
const MAX_SAMPLES: usize = 200_000;

#[derive(Debug, Clone, PartialEq)]
pub(crate) struct NurbsPath {
    curve: Nurbs,
    /// (s, u, heading) at each sample; s non-decreasing.
    samples: Vec<(f64, f64, f64)>,
}

impl NurbsPath {
    pub(crate) fn new(curve: Nurbs) -> Result<NurbsPath, TrajectoryError> {
        let pts = curve.control_points();
        let polygon: f64 = pts.windows(2).map(|w| match w {
            [a, b] => (b[0] - a[0]).hypot(b[1] - a[1]),
            _ => 0.0,
        }).sum();
        if !polygon.is_finite() {
            return Err(TrajectoryError::BadNumber { shape: "NURBS", what: "control polygon length".into(), constraint: "", value: polygon });
        }
        let wanted = (polygon / SAMPLE_STEP).ceil();
        let n = if wanted.is_finite() && wanted < MAX_SAMPLES as f64 { wanted as usize } else { MAX_SAMPLES };
        let n = n.max(MIN_SAMPLES_PER_POINT * pts.len()).min(MAX_SAMPLES);
        let (a, b) = curve.domain();
        let du = (b - a) / n as f64;
        let eps = (b - a) * 1e-7;
        let mut samples = Vec::with_capacity(n + 1);
        let mut s = 0.0;
        let mut prev: Option<[f64; 3]> = None;
        let mut prev_heading = 0.0;
        for i in 0..=n {
            let u = if i == n { b } else { a + i as f64 * du };
            let p = curve.point(u);
            if let Some(q) = prev {
                s += (p[0] - q[0]).hypot(p[1] - q[1]);
            }
            let (lo, hi) = (curve.point((u - eps).max(a)), curve.point((u + eps).min(b)));
            let (dx, dy) = (hi[0] - lo[0], hi[1] - lo[1]);
            // Where the tangent vanishes (coincident control points) keep the last heading.
            let heading = if dx.hypot(dy) > 1e-12 { angle::normalize(dy.atan2(dx)) } else { prev_heading };
            prev_heading = heading;
            samples.push((s, u, heading));
            prev = Some(p);
        }
        if !(s.is_finite() && s > 0.0) {
            return Err(TrajectoryError::ZeroLength { shape: "NURBS" });
        }
        // A first sample at a vanishing tangent borrows the heading of the second.
        if let (Some(second), Some(first)) = (samples.get(1).copied(), samples.first_mut()) {
            let p0 = curve.point(a);
            let (lo, hi) = (p0, curve.point(a + eps));
            if (hi[0] - lo[0]).hypot(hi[1] - lo[1]) <= 1e-12 {
                first.2 = second.2;
            }
        }
        Ok(NurbsPath { curve, samples })
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
        let p = self.curve.point(u0 + a * (u1 - u0));
        let turn = angle::diff(h1, h0);
        PathPoint {
            s,
            x: p[0],
            y: p[1],
            z: p[2],
            heading: angle::normalize(h0 + a * turn),
            curvature: if ds > 0.0 { turn / ds } else { 0.0 },
        }
    }

    /// (s, time) at every sample, time interpolated linearly in the parameter between the
    /// parameters where each control point's basis function peaks (esmini's rule).
    pub(crate) fn time_stamps(&self, times: &[f64]) -> Vec<(f64, f64)> {
        let n = self.curve.control_points().len();
        let mut peak_u = vec![f64::NEG_INFINITY; n];
        let mut peak_v = vec![f64::NEG_INFINITY; n];
        for &(_, u, _) in &self.samples {
            let (first, vals) = self.curve.basis_nonzero(u);
            for (i, v) in vals.into_iter().enumerate().map(|(r, v)| (first + r, v)) {
                if let (Some(pv), Some(pu)) = (peak_v.get_mut(i), peak_u.get_mut(i)) {
                    if v > *pv {
                        *pv = v;
                        *pu = u;
                    }
                }
            }
        }
        // Peaks move forward with the index; enforce it against rounding.
        let mut last = f64::NEG_INFINITY;
        for u in peak_u.iter_mut() {
            *u = u.max(last);
            last = *u;
        }
        let mut out = Vec::with_capacity(self.samples.len());
        let mut k = 0usize;
        for &(s, u, _) in &self.samples {
            while k + 2 < n && peak_u.get(k + 1).is_some_and(|&p| u >= p) {
                k += 1;
            }
            let (Some(&ua), Some(&ub), Some(&ta), Some(&tb)) = (peak_u.get(k), peak_u.get(k + 1), times.get(k), times.get(k + 1)) else {
                out.push((s, times.first().copied().unwrap_or(0.0)));
                continue;
            };
            let w = if ub > ua { ((u - ua) / (ub - ua)).clamp(0.0, 1.0) } else { 1.0 };
            out.push((s, ta + w * (tb - ta)));
        }
        out
    }
}

//! Arc length of a parametric cubic curve and its inverse (arc length → parameter),
//! shared by `poly3` and `paramPoly3` (s in OpenDRIVE is always arc length).

use super::gauss_legendre::integrate;

/// Hostile-input cap on table panels.
const MAX_PANELS: usize = 100_000;

/// Arc-length residual (m) below which one last Newton step is exact to well under 1e-12 m.
const RESIDUAL: f64 = 1e-8;

/// Coefficients of u(p) and v(p), each `[a, b, c, d]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CubicCurve {
    pub u: [f64; 4],
    pub v: [f64; 4],
}

fn eval(c: &[f64; 4], p: f64) -> f64 {
    c[0] + p * (c[1] + p * (c[2] + p * c[3]))
}
fn deriv(c: &[f64; 4], p: f64) -> f64 {
    c[1] + p * (2.0 * c[2] + p * 3.0 * c[3])
}
fn deriv2(c: &[f64; 4], p: f64) -> f64 {
    2.0 * c[2] + 6.0 * c[3] * p
}

impl CubicCurve {
    pub fn point(&self, p: f64) -> (f64, f64) {
        (eval(&self.u, p), eval(&self.v, p))
    }
    pub fn tangent(&self, p: f64) -> (f64, f64) {
        (deriv(&self.u, p), deriv(&self.v, p))
    }
    pub fn second(&self, p: f64) -> (f64, f64) {
        (deriv2(&self.u, p), deriv2(&self.v, p))
    }
    pub fn speed(&self, p: f64) -> f64 {
        let (du, dv) = self.tangent(p);
        // Not `hypot`: tangents of road geometry are far from overflow, and this is the hot
        // inner loop of arc length → parameter.
        (du * du + dv * dv).sqrt()
    }
}

/// Arc length at panel boundaries of p ∈ [0, p_max].
#[derive(Debug, Clone, PartialEq)]
pub struct ArcLengthTable {
    pub curve: CubicCurve,
    pub p_max: f64,
    panel: f64,
    /// Arc length at the start of each panel; last entry is the total length.
    s_at: Vec<f64>,
}

impl ArcLengthTable {
    /// Tabulate `curve` on [0, p_max]; `scale_hint` is a length in metres that sets panel count.
    pub fn new(curve: CubicCurve, p_max: f64, scale_hint: f64) -> ArcLengthTable {
        let p_max = p_max.max(0.0);
        let panels = ((scale_hint.abs() / 2.0).ceil().max(16.0) as usize).min(MAX_PANELS);
        let panel = if p_max > 0.0 { p_max / panels as f64 } else { 1.0 };
        let mut s_at = Vec::with_capacity(panels + 1);
        let mut s = 0.0;
        s_at.push(s);
        for i in 0..panels {
            let a = i as f64 * panel;
            s += integrate(a, a + panel, |p| curve.speed(p));
            s_at.push(s);
        }
        ArcLengthTable { curve, p_max, panel, s_at }
    }

    /// Total arc length of the curve on [0, p_max].
    pub fn total(&self) -> f64 {
        self.s_at.last().copied().unwrap_or(0.0)
    }

    /// The parameter p whose arc length from 0 is `s` (clamped to the curve).
    pub fn param_at(&self, s: f64) -> f64 {
        if self.p_max <= 0.0 {
            return 0.0;
        }
        let s = s.clamp(0.0, self.total());
        let i = self.s_at.partition_point(|&x| x <= s).saturating_sub(1).min(self.s_at.len().saturating_sub(2));
        let p0 = i as f64 * self.panel;
        let s0 = self.s_at.get(i).copied().unwrap_or(0.0);
        let p1 = (p0 + self.panel).min(self.p_max);
        // Start from the second-order Taylor inverse of S about p0 (S' = speed, S'' = its
        // derivative), then Newton on S(p) = s, bracketed to the panel. Once the residual is
        // below RESIDUAL the final Newton step leaves an error of order residual² · curvature.
        let ds = s - s0;
        let (du, dv) = self.curve.tangent(p0);
        let (ddu, ddv) = self.curve.second(p0);
        let v0 = (du * du + dv * dv).sqrt().max(1e-12);
        let a0 = (du * ddu + dv * ddv) / v0;
        let disc = v0 * v0 + 2.0 * a0 * ds;
        let mut p = if disc > 0.0 { p0 + 2.0 * ds / (v0 + disc.sqrt()) } else { p0 + ds / v0 };
        for _ in 0..8 {
            p = p.clamp(p0, p1);
            let f = s0 + integrate(p0, p, |q| self.curve.speed(q)) - s;
            p -= f / self.curve.speed(p).max(1e-12);
            if f.abs() < RESIDUAL {
                break;
            }
        }
        p.clamp(p0, p1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn param_at_inverts_the_arc_length_to_well_within_a_nanometre() {
        // A strongly curved normalized paramPoly3 (p ∈ [0, 1]) and an arc-length one.
        let curves = [
            (CubicCurve { u: [0.0, 40.0, -10.0, 5.0], v: [0.0, 0.0, 30.0, -12.0] }, 1.0),
            (CubicCurve { u: [0.0, 1.0, 0.0, -0.0004], v: [0.0, 0.0, 0.02, 0.0005] }, 60.0),
        ];
        for (curve, p_max) in curves {
            let table = ArcLengthTable::new(curve, p_max, 60.0);
            for k in 0..=200 {
                let s = table.total() * k as f64 / 200.0;
                let p = table.param_at(s);
                // Independent arc length: 2000 Gauss–Legendre panels from 0 to p.
                let n = 2000;
                let h = p / n as f64;
                let len: f64 = (0..n).map(|i| integrate(i as f64 * h, (i + 1) as f64 * h, |q| curve.speed(q))).sum();
                assert!((len - s).abs() < 1e-9, "s = {s}: arc length to p is {len}");
            }
        }
    }
}

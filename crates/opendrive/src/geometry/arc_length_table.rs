//! Arc length of a parametric cubic curve and its inverse (arc length → parameter),
//! shared by `poly3` and `paramPoly3` (s in OpenDRIVE is always arc length).

use super::gauss_legendre::integrate;

/// Hostile-input cap on table panels.
const MAX_PANELS: usize = 100_000;

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
        du.hypot(dv)
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
        // Newton on S(p) = s with S'(p) = speed(p), bracketed to the panel.
        let mut p = p0 + (s - s0) / self.curve.speed(p0).max(1e-12);
        for _ in 0..8 {
            p = p.clamp(p0, p1);
            let f = s0 + integrate(p0, p, |q| self.curve.speed(q)) - s;
            let step = f / self.curve.speed(p).max(1e-12);
            p -= step;
            if step.abs() < 1e-14 * (1.0 + p.abs()) {
                break;
            }
        }
        p.clamp(p0, p1)
    }
}

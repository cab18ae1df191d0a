//! Clothoid segments (curvature linear in s), evaluated exactly: the heading is a quadratic
//! in s and the position its integral, done with Gauss–Legendre quadrature from the
//! nearest tabulated point (at most `step` metres away).

use crate::angle;
use crate::pose::{PathPoint, Pose};

/// 8-point Gauss–Legendre nodes on [-1, 1] (positive half) and weights.
const GL_X: [f64; 4] = [0.183_434_642_495_649_8, 0.525_532_409_916_329, 0.796_666_477_413_626_7, 0.960_289_856_497_536_3];
const GL_W: [f64; 4] = [0.362_683_783_378_362, 0.313_706_645_877_887_3, 0.222_381_034_453_374_5, 0.101_228_536_290_376_3];

/// Most table points per segment (hostile lengths get a coarser table, never a huge one).
const MAX_TABLE: f64 = 20_000.0;

#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Spiral {
    start: Pose,
    k0: f64,
    /// dκ/ds
    dk: f64,
    length: f64,
    step: f64,
    /// (x, y) at s = i · step.
    table: Vec<(f64, f64)>,
}

impl Spiral {
    pub(crate) fn new(start: Pose, k0: f64, dk: f64, length: f64) -> Spiral {
        // ≤ 1 m and ≤ 0.5 rad of turning between table points keeps the quadrature exact
        // to rounding; the table size cap wins for hostile input.
        let kmax = k0.abs().max((k0 + dk * length).abs());
        let step = (0.5 / kmax).min(1.0).max(length / MAX_TABLE);
        let n = (length / step).ceil() as usize;
        let mut sp = Spiral { start, k0, dk, length, step, table: Vec::with_capacity(n + 1) };
        let (mut x, mut y) = (start.x, start.y);
        sp.table.push((x, y));
        for i in 0..n {
            let a = i as f64 * step;
            let b = ((i + 1) as f64 * step).min(length);
            let (dx, dy) = sp.integrate(a, b);
            x += dx;
            y += dy;
            sp.table.push((x, y));
        }
        sp
    }

    fn heading(&self, s: f64) -> f64 {
        self.start.heading + self.k0 * s + 0.5 * self.dk * s * s
    }

    /// ∫ (cos θ, sin θ) ds over [a, b].
    fn integrate(&self, a: f64, b: f64) -> (f64, f64) {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        let (mut cx, mut cy) = (0.0, 0.0);
        for (x, w) in GL_X.iter().zip(GL_W.iter()) {
            for s in [mid - half * x, mid + half * x] {
                let (sin, cos) = self.heading(s).sin_cos();
                cx += w * cos;
                cy += w * sin;
            }
        }
        (cx * half, cy * half)
    }

    /// Point at local arc length `s` (clamped to the segment).
    pub(crate) fn eval(&self, s: f64) -> PathPoint {
        let s = s.clamp(0.0, self.length);
        let i = ((s / self.step).floor() as usize).min(self.table.len().saturating_sub(1));
        let (x0, y0) = self.table.get(i).copied().unwrap_or((self.start.x, self.start.y));
        let (dx, dy) = self.integrate(i as f64 * self.step, s);
        PathPoint { s, x: x0 + dx, y: y0 + dy, z: self.start.z, heading: angle::normalize(self.heading(s)), curvature: self.k0 + self.dk * s }
    }

    /// The pose at the end (start of a following segment).
    pub(crate) fn end_pose(&self) -> Pose {
        let p = self.eval(self.length);
        Pose { x: p.x, y: p.y, z: p.z, heading: self.heading(self.length) }
    }
}

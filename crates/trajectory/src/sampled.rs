//! A curve replaced by esmini's one-metre polyline: vertices every metre of arc length, and the
//! last vertex (the true end) placed at the last whole metre, so along a curve of 15.5 m the
//! metre from 14 to 15 covers 1.5 m and s beyond 15 stays at the end. Positions are linear
//! between vertices, headings turn linearly. esmini moves entities along ClothoidSpline
//! trajectories this way.

use crate::angle;
use crate::pose::PathPoint;

#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Sampled {
    /// (s, x, y, z, heading) of each vertex; s strictly increasing.
    pts: Vec<[f64; 5]>,
}

impl Sampled {
    /// `at(s)` evaluates the exact curve of length `length` (≥ 1 m) at arc length s.
    pub(crate) fn new(length: f64, step: f64, at: impl Fn(f64) -> PathPoint) -> Sampled {
        let steps = (length / step).floor().max(1.0) as usize;
        let mut pts = Vec::with_capacity(steps + 1);
        for i in 0..=steps {
            let s = i as f64 * step;
            let p = if i < steps { at(s) } else { at(length) };
            pts.push([s, p.x, p.y, p.z, p.heading]);
        }
        Sampled { pts }
    }

    pub(crate) fn eval(&self, s: f64) -> PathPoint {
        let i = self.pts.partition_point(|p| p[0] <= s).saturating_sub(1).min(self.pts.len().saturating_sub(2));
        let (Some(a), Some(b)) = (self.pts.get(i), self.pts.get(i + 1)) else {
            let p = self.pts.first().copied().unwrap_or([0.0; 5]);
            return PathPoint { s, x: p[1], y: p[2], z: p[3], heading: p[4], curvature: 0.0 };
        };
        let ds = b[0] - a[0];
        let u = if ds > 0.0 { ((s - a[0]) / ds).clamp(0.0, 1.0) } else { 0.0 };
        let lerp = |k: usize| a[k] + u * (b[k] - a[k]);
        let turn = angle::diff(b[4], a[4]);
        PathPoint { s, x: lerp(1), y: lerp(2), z: lerp(3), heading: angle::normalize(a[4] + u * turn), curvature: if ds > 0.0 { turn / ds } else { 0.0 } }
    }
}

//! The reference line of a road: G1-continuous cubic Hermite pieces written as normalized
//! `paramPoly3` records, evaluated by the `opendrive` crate's own geometry (the reader's
//! arithmetic, so what is fitted here is what a reader evaluates), with projection of
//! world points to (s, t).
//!
//! The line does not have to follow the lanes closely: every lane border is written as an
//! offset from it, fitted afterwards. What it must do is be smooth, start and end
//! perpendicular to the road's end cross-sections (a lane section begins and ends on the
//! normal of its reference line), and keep its normals from folding within the road's width.

use crate::vec2::{to_segment, V2};
use opendrive::geometry::{PRange, ParamPoly3};
use opendrive::{Geometry, Shape};

/// Reference points per metre of line for the nearest-point search.
const SAMPLE_STEP: f64 = 0.5;
/// Newton steps of the projection.
const NEWTON_STEPS: usize = 8;

/// A point with its heading: where a Hermite piece starts or ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Knot {
    pub p: V2,
    pub hdg: f64,
}

/// A pose on the line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pose {
    pub p: V2,
    pub hdg: f64,
    pub curvature: f64,
}

impl Pose {
    /// Unit normal (left of the heading): t grows along it.
    pub(crate) fn normal(&self) -> V2 {
        V2::unit(self.hdg + std::f64::consts::FRAC_PI_2)
    }
    pub(crate) fn at_t(&self, t: f64) -> V2 {
        self.p.add(self.normal().scale(t))
    }
}

/// The cubic Hermite piece from `a` to `b` as a paramPoly3 in `a`'s frame, p ∈ [0, 1],
/// tangent magnitude = chord length (the usual choice: no loops for turns below ~120°).
pub(crate) fn hermite(a: Knot, b: Knot) -> ([f64; 4], [f64; 4]) {
    let d = b.p.sub(a.p);
    let m = d.len();
    let (s, c) = (-a.hdg).sin_cos();
    let q = V2::new(d.x * c - d.y * s, d.x * s + d.y * c);
    let t1 = V2::unit(b.hdg - a.hdg).scale(m);
    let u = [0.0, m, 3.0 * q.x - 2.0 * m - t1.x, m + t1.x - 2.0 * q.x];
    let v = [0.0, 0.0, 3.0 * q.y - t1.y, t1.y - 2.0 * q.y];
    (u, v)
}

/// One reference line: its plan-view records (s from 0) and sample points for projection.
#[derive(Debug, Clone)]
pub(crate) struct RefLine {
    pub geometries: Vec<Geometry>,
    pub length: f64,
    /// Knot stations (the s of each record start, then the end).
    pub knots_s: Vec<f64>,
    samples: Vec<(f64, V2)>,
}

impl RefLine {
    /// The line through `knots` (at least two), one Hermite piece between each pair.
    pub(crate) fn through(knots: &[Knot]) -> RefLine {
        let mut geometries = Vec::with_capacity(knots.len().saturating_sub(1));
        let mut s = 0.0;
        let mut knots_s = vec![0.0];
        for w in knots.windows(2) {
            let (u, v) = hermite(w[0], w[1]);
            let chord = w[0].p.dist(w[1].p);
            let probe = ParamPoly3::new(u, v, PRange::Normalized, chord.max(1e-9));
            let len = probe.arc_length();
            if len.is_nan() || len <= 1e-9 {
                continue;
            }
            let pp = ParamPoly3::new(u, v, PRange::Normalized, len);
            geometries.push(Geometry::new(s, w[0].p.x, w[0].p.y, w[0].hdg, len, Shape::ParamPoly3(pp)));
            s += len;
            knots_s.push(s);
        }
        let mut line = RefLine { geometries, length: s, knots_s, samples: Vec::new() };
        line.samples = line.sample_points();
        line
    }

    /// The line of existing plan-view records (s from 0, in order).
    pub(crate) fn of(geometries: Vec<Geometry>) -> RefLine {
        let length = geometries.last().map_or(0.0, |g| g.s + g.length);
        let mut knots_s: Vec<f64> = geometries.iter().map(|g| g.s).collect();
        knots_s.push(length);
        let mut line = RefLine { geometries, length, knots_s, samples: Vec::new() };
        line.samples = line.sample_points();
        line
    }

    fn sample_points(&self) -> Vec<(f64, V2)> {
        let mut out = Vec::new();
        for g in &self.geometries {
            let n = ((g.length / SAMPLE_STEP).ceil() as usize).clamp(4, 20_000);
            for k in 0..n {
                let ds = g.length * k as f64 / n as f64;
                let p = g.pose_at(ds);
                out.push((g.s + ds, V2::new(p.x, p.y)));
            }
        }
        let end = self.pose(self.length);
        out.push((self.length, end.p));
        out
    }

    fn geometry_at(&self, s: f64) -> Option<&Geometry> {
        let i = self.geometries.partition_point(|g| g.s <= s).saturating_sub(1);
        self.geometries.get(i)
    }

    /// Pose at `s` (clamped to the line).
    pub(crate) fn pose(&self, s: f64) -> Pose {
        let s = s.clamp(0.0, self.length);
        match self.geometry_at(s) {
            Some(g) => {
                let p = g.pose_at((s - g.s).clamp(0.0, g.length));
                Pose { p: V2::new(p.x, p.y), hdg: p.hdg, curvature: p.curvature }
            }
            None => Pose { p: V2::new(0.0, 0.0), hdg: 0.0, curvature: 0.0 },
        }
    }

    /// (s, t) of the foot of the normal through `p` nearest to `p`; `near` restricts the
    /// search to ±`window` m around a station (marching along a border).
    pub(crate) fn project(&self, p: V2, near: Option<(f64, f64)>) -> (f64, f64) {
        let mut best = (f64::INFINITY, 0.0);
        let (lo, hi) = match near {
            Some((c, r)) => {
                (self.samples.partition_point(|x| x.0 < c - r).saturating_sub(1), (self.samples.partition_point(|x| x.0 <= c + r) + 1).min(self.samples.len()))
            }
            None => (0, self.samples.len()),
        };
        for w in self.samples.get(lo..hi).unwrap_or(&[]).windows(2) {
            let ((s0, a), (s1, b)) = (w[0], w[1]);
            let (d, u) = to_segment(p, a, b);
            if d < best.0 {
                best = (d, s0 + u * (s1 - s0));
            }
        }
        if !best.0.is_finite() {
            // an empty window: search everywhere
            return if near.is_some() { self.project(p, None) } else { (0.0, 0.0) };
        }
        let mut s = best.1;
        for _ in 0..NEWTON_STEPS {
            let pose = self.pose(s);
            let tangent = V2::unit(pose.hdg);
            let d = p.sub(pose.p);
            let t = d.dot(pose.normal());
            let denom = (1.0 - pose.curvature * t).max(0.05);
            let step = d.dot(tangent) / denom;
            let next = (s + step).clamp(0.0, self.length);
            let done = (next - s).abs() < 1e-12;
            s = next;
            if done {
                break;
            }
        }
        let pose = self.pose(s);
        (s, p.sub(pose.p).dot(pose.normal()))
    }
}

/// Unit tangent directions of a polyline at its vertices (central differences; end
/// vertices take their segment's direction).
fn vertex_headings(m: &[V2]) -> Vec<f64> {
    let n = m.len();
    (0..n)
        .map(|i| {
            let a = m[i.saturating_sub(1)];
            let b = m[(i + 1).min(n - 1)];
            let d = b.sub(a);
            if d.len() > 0.0 {
                d.angle()
            } else {
                0.0
            }
        })
        .collect()
}

/// Largest distance of the vertices `m[i..=j]` from the Hermite piece between knots `a`, `b`.
fn piece_deviation(m: &[V2], i: usize, j: usize, a: Knot, b: Knot) -> (f64, usize) {
    let (u, v) = hermite(a, b);
    let (s, c) = a.hdg.sin_cos();
    let n = 32;
    let pts: Vec<V2> = (0..=n)
        .map(|k| {
            let p = k as f64 / n as f64;
            let lu = u[0] + p * (u[1] + p * (u[2] + p * u[3]));
            let lv = v[0] + p * (v[1] + p * (v[2] + p * v[3]));
            V2::new(a.p.x + lu * c - lv * s, a.p.y + lu * s + lv * c)
        })
        .collect();
    let mut worst = (0.0, (i + j) / 2);
    for (k, q) in m.iter().enumerate().take(j).skip(i + 1) {
        let d = crate::vec2::to_polyline(*q, &pts);
        if d > worst.0 {
            worst = (d, k);
        }
    }
    worst
}

/// Knots of a smooth line along the polyline `m` from `start` to `end` (headings forced
/// there), staying within `tol` of `m`'s vertices where it can; more knots where `m` bends.
pub(crate) fn knots_along(m: &[V2], start: Knot, end: Knot, tol: f64, max_knots: usize) -> Vec<Knot> {
    let hdgs = vertex_headings(m);
    let last = m.len().saturating_sub(1);
    // (vertex index, knot), first and last forced
    let mut knots: Vec<(usize, Knot)> = vec![(0, start), (last, end)];
    let mut k = 0;
    while k + 1 < knots.len() {
        let ((i, a), (j, b)) = (knots[k], knots[k + 1]);
        if j > i + 1 && knots.len() < max_knots {
            let (dev, at) = piece_deviation(m, i, j, a, b);
            if dev > tol {
                let (Some(&p), Some(&h)) = (m.get(at), hdgs.get(at)) else { break };
                knots.insert(k + 1, (at, Knot { p, hdg: h }));
                continue;
            }
        }
        k += 1;
    }
    knots.into_iter().map(|(_, k)| k).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_line_projection() {
        let line = RefLine::through(&[Knot { p: V2::new(0.0, 0.0), hdg: 0.0 }, Knot { p: V2::new(100.0, 0.0), hdg: 0.0 }]);
        assert!((line.length - 100.0).abs() < 1e-9);
        let (s, t) = line.project(V2::new(30.0, 2.0), None);
        assert!((s - 30.0).abs() < 1e-9 && (t - 2.0).abs() < 1e-9);
    }

    #[test]
    fn quarter_circle_knots_follow_the_arc() {
        let r = 50.0;
        let m: Vec<V2> = (0..=90).map(|k| f64::from(k).to_radians()).map(|a| V2::new(r * a.sin(), r - r * a.cos())).collect();
        let start = Knot { p: m[0], hdg: 0.0 };
        let end = Knot { p: m[90], hdg: std::f64::consts::FRAC_PI_2 };
        let knots = knots_along(&m, start, end, 0.01, 1000);
        let line = RefLine::through(&knots);
        for q in &m {
            let (s, t) = line.project(*q, None);
            assert!(t.abs() < 0.011, "s {s}: t {t}");
        }
        assert!((line.length - r * std::f64::consts::FRAC_PI_2).abs() < 0.05);
    }
}

//! Lane borders as lateral offsets t(s) from the reference line, and their fit by cubic
//! polynomials. A border is a lanelet bound polyline; its offset at s is where the normal
//! of the reference line at s meets it (exact, by line intersection), so a fitted t(s) that
//! is within ε of that offset puts the written border within ε of the bound at every s.
//!
//! All borders of a lane section are fitted on common pieces (so a lane's width, the
//! difference of two borders, is one cubic per piece); each piece interpolates the exact
//! offsets at its ends (the border is continuous), fits the samples between by least
//! squares and is checked at them and halfway between them (points it was not fitted to);
//! pieces are made as long as the tolerance allows, and always break at the reference
//! line's knots (where its curvature, and so the offsets' slope, may jump).

use crate::reference::RefLine;
use crate::vec2::V2;

/// Spacing of the fit samples between bound vertices (m).
const SAMPLE_STEP: f64 = 0.5;
/// Samples closer than this in s are one sample.
const SAME_S: f64 = 1e-7;

/// A bound polyline seen from the reference line.
#[derive(Debug, Clone)]
pub(crate) struct Border {
    pts: Vec<V2>,
    /// (s, t) of each vertex, s non-decreasing.
    st: Vec<(f64, f64)>,
    /// Largest amount (m of s) by which the polyline ran backwards along the line.
    pub backwards: f64,
}

impl Border {
    /// Projects the vertices of `pts` (in driving order along +s) onto `line`.
    pub(crate) fn new(pts: &[V2], line: &RefLine) -> Border {
        let mut st: Vec<(f64, f64)> = Vec::with_capacity(pts.len());
        let mut backwards: f64 = 0.0;
        for (i, &p) in pts.iter().enumerate() {
            // the first vertex lies on the start cross-section (s = 0: on a closed loop the end
            // is as near), each next one near the previous
            let near = match (st.last(), i.checked_sub(1).and_then(|k| pts.get(k))) {
                (Some(&(s, _)), Some(prev)) => Some((s, 20.0 + 2.0 * prev.dist(p))),
                _ => Some((0.0, 20.0)),
            };
            let (mut s, t) = line.project(p, near);
            if let Some(&(last, _)) = st.last() {
                if s < last {
                    backwards = backwards.max(last - s);
                    s = last;
                }
            }
            st.push((s, t));
        }
        Border { pts: pts.to_vec(), st, backwards }
    }

    /// Stations of the vertices.
    pub(crate) fn stations(&self) -> impl Iterator<Item = f64> + '_ {
        self.st.iter().map(|&(s, _)| s)
    }

    /// The offset of the border on the normal at `s` (the segment lines are extended past
    /// the ends).
    pub(crate) fn t_at(&self, s: f64, line: &RefLine) -> f64 {
        let n = self.st.len();
        if n == 0 {
            return 0.0;
        }
        if n == 1 {
            return self.st[0].1;
        }
        let i = self.st.partition_point(|&(si, _)| si <= s).clamp(1, n - 1) - 1;
        let (a, b) = (self.pts[i], self.pts[i + 1]);
        let pose = line.pose(s);
        let nrm = pose.normal();
        let ab = b.sub(a);
        let den = nrm.cross(ab);
        let (s0, t0) = self.st[i];
        let (s1, t1) = self.st[i + 1];
        if den.abs() > 1e-9 * ab.len().max(1e-9) {
            let t = a.sub(pose.p).cross(ab) / den;
            // a hit far outside the segment means the normal runs along it: interpolate
            let hit = pose.at_t(t);
            let u = if ab.dot(ab) > 0.0 { hit.sub(a).dot(ab) / ab.dot(ab) } else { 0.0 };
            if (-0.5..=1.5).contains(&u) || i == 0 || i + 2 == n {
                return t;
            }
        }
        if s1 > s0 {
            t0 + (t1 - t0) * ((s - s0) / (s1 - s0)).clamp(0.0, 1.0)
        } else {
            t0
        }
    }
}

/// `a + b·ds + c·ds² + d·ds³` from `s` on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Cubic {
    pub s: f64,
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub d: f64,
}

impl Cubic {
    pub(crate) fn value(&self, s: f64) -> f64 {
        let x = s - self.s;
        self.a + x * (self.b + x * (self.c + x * self.d))
    }
    /// Difference of two cubics starting at the same s.
    pub(crate) fn minus(&self, o: &Cubic) -> Cubic {
        Cubic { s: self.s, a: self.a - o.a, b: self.b - o.b, c: self.c - o.c, d: self.d - o.d }
    }
}

/// The cubic through (s0, y0) and (s1, y1) closest (least squares) to the samples between.
fn constrained_fit(s: &[f64], y: &[f64]) -> Cubic {
    let n = s.len();
    let (s0, s1) = (s[0], s[n - 1]);
    let (y0, y1) = (y[0], y[n - 1]);
    let len = s1 - s0;
    if n < 3 || len <= 0.0 {
        let b = if len > 0.0 { (y1 - y0) / len } else { 0.0 };
        return Cubic { s: s0, a: y0, b, c: 0.0, d: 0.0 };
    }
    // y ≈ line + x(1−x)(c1 + c2 x), x ∈ [0, 1]
    let (mut a11, mut a12, mut a22, mut r1, mut r2) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for k in 1..n - 1 {
        let x = (s[k] - s0) / len;
        let res = y[k] - (y0 + (y1 - y0) * x);
        let f1 = x * (1.0 - x);
        let f2 = f1 * x;
        a11 += f1 * f1;
        a12 += f1 * f2;
        a22 += f2 * f2;
        r1 += f1 * res;
        r2 += f2 * res;
    }
    let det = a11 * a22 - a12 * a12;
    let (c1, c2) = if det.abs() > 1e-18 * (a11 * a22).max(1e-300) {
        ((r1 * a22 - r2 * a12) / det, (a11 * r2 - a12 * r1) / det)
    } else if a11 > 0.0 {
        (r1 / a11, 0.0)
    } else {
        (0.0, 0.0)
    };
    let (a1, a2, a3) = ((y1 - y0) + c1, c2 - c1, -c2);
    Cubic { s: s0, a: y0, b: a1 / len, c: a2 / (len * len), d: a3 / (len * len * len) }
}

/// The fitted borders of one lane section.
#[derive(Debug, Clone)]
pub(crate) struct FittedBorders {
    /// Start s of each piece (the first is the section start).
    pub pieces: Vec<f64>,
    /// Per border, one cubic per piece.
    pub cubics: Vec<Vec<Cubic>>,
    /// Largest |fitted − exact| over all samples (m).
    pub max_error: f64,
}

/// Fits all `borders` on [s0, s1] with common pieces, breaking at `breaks` (s values). A
/// border given by two polylines (the bounds of two neighbours that should coincide) is
/// their mean.
pub(crate) fn fit_section(line: &RefLine, borders: &[Vec<Border>], s0: f64, s1: f64, breaks: &[f64], tol: f64) -> FittedBorders {
    let mut grid: Vec<f64> = vec![s0, s1];
    for b in borders.iter().flatten() {
        grid.extend(b.stations());
    }
    grid.extend(breaks.iter().copied());
    // hostile lengths: at most 20,000 samples between the vertices
    let n_uniform = (((s1 - s0) / SAMPLE_STEP).ceil() as usize).min(20_000);
    grid.extend((1..n_uniform).map(|k| s0 + (s1 - s0) * k as f64 / n_uniform as f64));
    grid.retain(|s| s.is_finite() && *s >= s0 && *s <= s1);
    grid.sort_by(f64::total_cmp);
    grid.dedup_by(|a, b| (*a - *b).abs() < SAME_S);
    // midpoints too: a cubic through four samples is exact at them and may still miss the
    // corner of a bound between them
    let mids: Vec<f64> = grid.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    grid.extend(mids);
    grid.sort_by(f64::total_cmp);
    grid.dedup_by(|a, b| (*a - *b).abs() < SAME_S);
    if let Some(last) = grid.last_mut() {
        *last = s1;
    }
    let mean = |set: &Vec<Border>, s: f64| set.iter().map(|b| b.t_at(s, line)).sum::<f64>() / set.len().max(1) as f64;
    let values: Vec<Vec<f64>> = borders.iter().map(|set| grid.iter().map(|&s| mean(set, s)).collect()).collect();
    // check points halfway between the samples, not fitted: a piece whose samples crowd at
    // one end is otherwise free to bulge in its empty part (ghost_route: 17 cm within 0.2 m
    // where a bend ends, every sample within the tolerance). The border there is taken as
    // the chord of its neighbouring samples: they are at most ~0.25 m apart and every kink of
    // a bound is a sample, so the chord is within h²/8·|t''| (a millimetre for t'' = 0.1/m)
    // and costs no projection
    let checks: Vec<f64> = grid.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let check_values: Vec<Vec<f64>> = values.iter().map(|ys| ys.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect()).collect();
    let mut mandatory: Vec<usize> = breaks.iter().map(|&b| grid.partition_point(|&g| g < b - SAME_S)).filter(|&i| i > 0 && i + 1 < grid.len()).collect();
    mandatory.push(grid.len().saturating_sub(1));
    mandatory.sort_unstable();
    mandatory.dedup();

    let fit = |i: usize, j: usize| -> (Vec<Cubic>, f64) {
        let s = &grid[i..=j];
        let mut worst: f64 = 0.0;
        let cubics = values
            .iter()
            .zip(&check_values)
            .map(|(ys, cs)| {
                let y = &ys[i..=j];
                let c = constrained_fit(s, y);
                for (sk, yk) in s.iter().zip(y).chain(checks[i..j].iter().zip(&cs[i..j])) {
                    worst = worst.max((c.value(*sk) - yk).abs());
                }
                c
            })
            .collect();
        (cubics, worst)
    };

    let mut pieces = Vec::new();
    let mut cubics: Vec<Vec<Cubic>> = vec![Vec::new(); borders.len()];
    let mut max_error: f64 = 0.0;
    let mut i = 0;
    while i + 1 < grid.len() {
        let limit = mandatory.iter().copied().find(|&m| m > i).unwrap_or(grid.len() - 1);
        let (mut best_j, mut best) = (i + 1, fit(i, i + 1));
        let whole = fit(i, limit);
        if whole.1 <= tol {
            (best_j, best) = (limit, whole);
        } else {
            // largest j that fits (bisection; the error grows with the piece)
            let (mut lo, mut hi) = (i + 1, limit);
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                let f = fit(i, mid);
                if f.1 <= tol {
                    (lo, best_j, best) = (mid, mid, f);
                } else {
                    hi = mid;
                }
            }
        }
        pieces.push(grid[i]);
        max_error = max_error.max(best.1);
        for (k, c) in best.0.into_iter().enumerate() {
            cubics[k].push(c);
        }
        i = best_j;
    }
    FittedBorders { pieces, cubics, max_error }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::Knot;

    #[test]
    fn constrained_fit_reproduces_a_cubic() {
        let s: Vec<f64> = (0..20).map(|k| 3.0 + f64::from(k) * 0.7).collect();
        let f = |x: f64| 1.0 + 0.5 * (x - 3.0) - 0.02 * (x - 3.0).powi(2) + 0.001 * (x - 3.0).powi(3);
        let y: Vec<f64> = s.iter().map(|&x| f(x)).collect();
        let c = constrained_fit(&s, &y);
        for &x in &s {
            assert!((c.value(x) - f(x)).abs() < 1e-9);
        }
    }

    #[test]
    fn no_bulge_between_samples_that_crowd_at_a_piece_end() {
        // a border that turns away sharply just before the end, its vertices crowding there:
        // the pieces must follow it between the samples too, not only at them
        let line = RefLine::through(&[Knot { p: V2::new(0.0, 0.0), hdg: 0.0 }, Knot { p: V2::new(10.0, 0.0), hdg: 0.0 }]);
        let xs = [0.0, 9.9990, 9.9993, 9.9995, 9.9997, 9.9998, 10.0];
        let border: Vec<V2> = xs.iter().map(|&x| V2::new(x, -3.0 + if x > 9.9994 { 0.3 * (x - 9.9994) } else { 0.0 })).collect();
        let b = Border::new(&border, &line);
        // a piece forced to start halfway between the last uniform sample and the crowd
        let fitted = fit_section(&line, &[vec![b.clone()]], 0.0, 10.0, &[0.5 * (9.5 + 9.999)], 0.001);
        for k in 0..=10_000 {
            let s = f64::from(k) * 0.001;
            let i = fitted.pieces.partition_point(|&p| p <= s).saturating_sub(1);
            let err = (fitted.cubics[0][i].value(s) - b.t_at(s, &line)).abs();
            assert!(err <= 0.0011, "s {s}: fitted border {err} m off");
        }
    }

    #[test]
    fn a_widening_lane_on_a_straight_line() {
        let line = RefLine::through(&[Knot { p: V2::new(0.0, 0.0), hdg: 0.0 }, Knot { p: V2::new(100.0, 0.0), hdg: 0.0 }]);
        let right: Vec<V2> = (0..=10).map(|k| f64::from(k) * 10.0).map(|x| V2::new(x, -3.0 - 0.0001 * x * x)).collect();
        let b = Border::new(&right, &line);
        assert!((b.t_at(55.0, &line) - (-3.0 - 0.0001 * 55.0 * 55.0)).abs() < 0.01);
        let fitted = fit_section(&line, &[vec![b]], 0.0, 100.0, &[], 0.005);
        assert!(fitted.max_error <= 0.005);
        assert!(fitted.pieces.len() < 10, "{} pieces", fitted.pieces.len());
    }
}

//! A rational B-spline curve: validation and evaluation with de Boor's algorithm in
//! homogeneous coordinates (w·x, w·y, w·z, w).

use crate::error::Error;

/// Highest order accepted: evaluation costs order² per point (hostile input).
pub(crate) const MAX_ORDER: usize = 32;

#[derive(Debug, Clone, PartialEq)]
pub struct Nurbs {
    /// Order = degree + 1.
    order: usize,
    /// (x, y, z, weight)
    points: Vec<[f64; 4]>,
    knots: Vec<f64>,
}

impl Nurbs {
    /// `points` are (x, y, z, weight). Knots must number points + order, be finite and
    /// non-decreasing, and span a non-empty domain [knot[order-1], knot[points]].
    pub fn new(order: u32, points: Vec<[f64; 4]>, knots: Vec<f64>) -> Result<Nurbs, Error> {
        let n = points.len();
        let k = order as usize;
        if k < 2 || k > n {
            return Err(Error::BadOrder { order, control_points: n });
        }
        if k > MAX_ORDER {
            return Err(Error::TooMany { shape: "NURBS", what: "as order", max: MAX_ORDER, found: k });
        }
        if knots.len() != n + k {
            return Err(Error::KnotCount { expected: n + k, found: knots.len() });
        }
        for (i, &u) in knots.iter().enumerate() {
            if !u.is_finite() {
                return Err(Error::BadNumber { shape: "NURBS", what: format!("knot {i}"), constraint: "", value: u });
            }
        }
        if let Some(i) = knots.windows(2).position(|w| matches!(w, [a, b] if b < a)) {
            return Err(Error::NotMonotone { shape: "NURBS", what: "knots", index: i + 1 });
        }
        for (i, p) in points.iter().enumerate() {
            if !(p[3].is_finite() && p[3] > 0.0) {
                return Err(Error::BadNumber { shape: "NURBS", what: format!("weight of control point {i}"), constraint: " > 0", value: p[3] });
            }
        }
        let nurbs = Nurbs { order: k, points, knots };
        let (a, b) = nurbs.domain();
        if b.partial_cmp(&a) != Some(std::cmp::Ordering::Greater) {
            return Err(Error::EmptyDomain);
        }
        Ok(nurbs)
    }

    pub fn order(&self) -> usize {
        self.order
    }
    pub fn control_points(&self) -> &[[f64; 4]] {
        &self.points
    }

    /// Parameter range where the basis functions sum to one.
    pub fn domain(&self) -> (f64, f64) {
        let a = self.knots.get(self.order - 1).copied().unwrap_or(0.0);
        let b = self.knots.get(self.points.len()).copied().unwrap_or(0.0);
        (a, b)
    }

    /// Knot span index j with knot[j] ≤ u < knot[j+1], j in [order-1, n-1]; u is clamped
    /// to the domain and its right end belongs to the last non-empty span.
    fn span(&self, u: f64) -> (usize, f64) {
        let (a, b) = self.domain();
        let u = u.clamp(a, b);
        let lo = self.order - 1;
        let hi = self.points.len() - 1;
        let knot = |i: usize| self.knots.get(i).copied().unwrap_or(0.0);
        let mut j = self.knots.partition_point(|&k| k <= u).saturating_sub(1).clamp(lo, hi);
        // At the right end (or inside repeated knots) step back to a non-empty span.
        while j > lo && knot(j + 1) <= knot(j) {
            j -= 1;
        }
        (j, u)
    }

    /// Point (x, y, z) at parameter `u` (clamped to the domain).
    pub fn point(&self, u: f64) -> [f64; 3] {
        let (j, u) = self.span(u);
        let p = self.order - 1;
        // Homogeneous control points of the span: d[r] = P[j - p + r].
        let mut d: Vec<[f64; 4]> = (0..=p)
            .map(|r| {
                let c = self.points.get(j + r - p).copied().unwrap_or([0.0, 0.0, 0.0, 1.0]);
                [c[0] * c[3], c[1] * c[3], c[2] * c[3], c[3]]
            })
            .collect();
        for level in 1..=p {
            for r in (level..=p).rev() {
                let i = j + r - p;
                let (ki, kn) = (self.knots.get(i).copied().unwrap_or(0.0), self.knots.get(i + p + 1 - level).copied().unwrap_or(0.0));
                let alpha = if kn > ki { (u - ki) / (kn - ki) } else { 0.0 };
                let (Some(&lo), Some(&hi)) = (d.get(r - 1), d.get(r)) else { continue };
                if let Some(slot) = d.get_mut(r) {
                    for c in 0..4 {
                        slot[c] = (1.0 - alpha) * lo[c] + alpha * hi[c];
                    }
                }
            }
        }
        let h = d.get(p).copied().unwrap_or([0.0, 0.0, 0.0, 1.0]);
        let w = if h[3] != 0.0 { h[3] } else { 1.0 };
        [h[0] / w, h[1] / w, h[2] / w]
    }

    /// Point (x, y, z) at parameter `u` as esmini's NurbsShape::EvaluateInternal sums it: the
    /// rational weight takes every basis value, but a control point adds to the position only
    /// where its basis value is above SMALL_NUMBER (1e-6). Right after a knot (and at the start)
    /// a basis value that small is left out of the sum while the weight still counts it, which
    /// pulls the point towards the origin by up to about 1e-6 of its coordinates (a millimetre
    /// at a thousand metres).
    pub fn esmini_point(&self, u: f64) -> [f64; 3] {
        // The basis values on the stack for the usual orders (a path is evaluated per step).
        let mut stack = [0.0; 8];
        let mut heap = Vec::new();
        let buf: &mut [f64] = if self.order <= stack.len() {
            &mut stack[..self.order]
        } else {
            heap.resize(self.order, 0.0);
            &mut heap
        };
        let first = self.basis_into(u, buf);
        let vals: &[f64] = buf;
        let mut weight = 0.0;
        let mut sum = [0.0; 3];
        for (r, v) in vals.iter().enumerate() {
            let Some(c) = self.points.get(first + r) else { continue };
            weight += v * c[3];
        }
        if weight == 0.0 {
            return self.point(u);
        }
        for (r, v) in vals.iter().enumerate() {
            let Some(c) = self.points.get(first + r) else { continue };
            if *v > crate::ESMINI_SMALL {
                for k in 0..3 {
                    sum[k] += v * c[k] * c[3] / weight;
                }
            }
        }
        sum
    }

    /// Values of the (non-rational) basis functions N_i(u) for every control point.
    pub fn basis(&self, u: f64) -> Vec<f64> {
        let (first, vals) = self.basis_nonzero(u);
        let mut out = vec![0.0; self.points.len()];
        for (r, v) in vals.into_iter().enumerate() {
            if let Some(slot) = out.get_mut(first + r) {
                *slot = v;
            }
        }
        out
    }

    /// The order-many basis functions that may be non-zero at u: (index of the first, values).
    pub(crate) fn basis_nonzero(&self, u: f64) -> (usize, Vec<f64>) {
        let mut nvals = vec![0.0; self.order];
        let first = self.basis_into(u, &mut nvals);
        (first, nvals)
    }

    /// [`Nurbs::basis_nonzero`] written into `nvals` (at least order long): the index of the
    /// first control point; the values are `nvals[..order]`.
    fn basis_into(&self, u: f64, nvals: &mut [f64]) -> usize {
        let (j, u) = self.span(u);
        let p = self.order - 1;
        // Cox–de Boor, triangular scheme on the p+1 functions non-zero in span j.
        nvals.iter_mut().for_each(|v| *v = 0.0);
        if let Some(f) = nvals.first_mut() {
            *f = 1.0;
        }
        let knot = |i: usize| self.knots.get(i).copied().unwrap_or(0.0);
        for deg in 1..=p {
            let mut saved = 0.0;
            for r in 0..deg {
                // N_{j-deg+1+r, deg-1} sits at nvals[r]
                let left_i = j + r + 1;
                let right_i = j + r + 1 - deg;
                let (kl, kr) = (knot(left_i), knot(right_i));
                let nr = nvals.get(r).copied().unwrap_or(0.0);
                let temp = if kl > kr { nr / (kl - kr) } else { 0.0 };
                if let Some(slot) = nvals.get_mut(r) {
                    *slot = saved + (kl - u) * temp;
                }
                saved = (u - kr) * temp;
            }
            if let Some(slot) = nvals.get_mut(deg) {
                *slot = saved;
            }
        }
        j - p
    }
}

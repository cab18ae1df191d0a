//! Plane vectors and polyline helpers in f64: the small arithmetic every other module uses
//! (lanelet bounds come in as `commonroad::Point`s, geometry works on `V2`).

/// A point or direction in the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct V2 {
    pub x: f64,
    pub y: f64,
}

impl V2 {
    pub(crate) const fn new(x: f64, y: f64) -> V2 {
        V2 { x, y }
    }
    pub(crate) fn of(p: &commonroad::Point) -> V2 {
        V2 { x: p.x, y: p.y }
    }
    pub(crate) fn add(self, o: V2) -> V2 {
        V2::new(self.x + o.x, self.y + o.y)
    }
    pub(crate) fn sub(self, o: V2) -> V2 {
        V2::new(self.x - o.x, self.y - o.y)
    }
    pub(crate) fn scale(self, k: f64) -> V2 {
        V2::new(self.x * k, self.y * k)
    }
    pub(crate) fn dot(self, o: V2) -> f64 {
        self.x * o.x + self.y * o.y
    }
    pub(crate) fn cross(self, o: V2) -> f64 {
        self.x * o.y - self.y * o.x
    }
    pub(crate) fn len(self) -> f64 {
        self.x.hypot(self.y)
    }
    pub(crate) fn dist(self, o: V2) -> f64 {
        self.sub(o).len()
    }
    /// Unit vector at angle `a` (rad, counter-clockwise from +x).
    pub(crate) fn unit(a: f64) -> V2 {
        let (s, c) = a.sin_cos();
        V2::new(c, s)
    }
    pub(crate) fn angle(self) -> f64 {
        self.y.atan2(self.x)
    }
    pub(crate) fn lerp(self, o: V2, u: f64) -> V2 {
        V2::new(self.x + (o.x - self.x) * u, self.y + (o.y - self.y) * u)
    }
    pub(crate) fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
}

/// Distance from `p` to the segment `a`–`b` and the segment parameter of the nearest point.
pub(crate) fn to_segment(p: V2, a: V2, b: V2) -> (f64, f64) {
    let d = b.sub(a);
    let l2 = d.dot(d);
    let u = if l2 > 0.0 { (p.sub(a).dot(d) / l2).clamp(0.0, 1.0) } else { 0.0 };
    (p.dist(a.lerp(b, u)), u)
}

/// Distance from `p` to a polyline (infinite for an empty one).
pub(crate) fn to_polyline(p: V2, line: &[V2]) -> f64 {
    match line {
        [] => f64::INFINITY,
        [only] => p.dist(*only),
        _ => line.windows(2).map(|w| to_segment(p, w[0], w[1]).0).fold(f64::INFINITY, f64::min),
    }
}

/// Length of a polyline.
pub(crate) fn length(line: &[V2]) -> f64 {
    line.windows(2).map(|w| w[0].dist(w[1])).sum()
}

/// The polyline without consecutive points closer than `eps` (the last point is kept).
pub(crate) fn dedup(line: &[V2], eps: f64) -> Vec<V2> {
    let mut out: Vec<V2> = Vec::with_capacity(line.len());
    for (i, &p) in line.iter().enumerate() {
        let last = i + 1 == line.len();
        let n = out.len();
        match out.last_mut() {
            Some(q) if q.dist(p) <= eps => {
                // the end point stays exact (the start of whatever follows)
                if last && n > 1 {
                    *q = p;
                }
            }
            _ => out.push(p),
        }
    }
    out
}

/// Segments in a grid of square cells, for nearest-segment queries with a cap.
pub(crate) struct SegmentIndex {
    cell: f64,
    cells: std::collections::HashMap<(i64, i64), Vec<(V2, V2)>>,
}

impl SegmentIndex {
    /// Indexes the segments of the polylines in `lines` with cells of at least `cell` m
    /// (more for hostile lengths: at most about two million cell entries). A segment is
    /// entered in the cells it passes through.
    pub(crate) fn new<'a>(lines: impl IntoIterator<Item = &'a [V2]> + Clone, cell: f64) -> SegmentIndex {
        let total: f64 = lines.clone().into_iter().map(length).sum();
        let cell = if cell.is_finite() && cell > 0.0 { cell } else { 1.0 };
        let cell = cell.max(total / 1_000_000.0);
        let mut cells: std::collections::HashMap<(i64, i64), Vec<(V2, V2)>> = std::collections::HashMap::new();
        let key = |p: V2| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
        for line in lines {
            let segs: Vec<(V2, V2)> = match line {
                [only] => vec![(*only, *only)],
                _ => line.windows(2).map(|w| (w[0], w[1])).collect(),
            };
            for (a, b) in segs {
                let n = ((a.dist(b) / (0.25 * cell)).ceil() as usize).clamp(1, 8_000_000);
                let mut last = None;
                for k in 0..=n {
                    let c = key(a.lerp(b, k as f64 / n as f64));
                    if last != Some(c) {
                        let v = cells.entry(c).or_default();
                        if v.last() != Some(&(a, b)) {
                            v.push((a, b));
                        }
                        last = Some(c);
                    }
                }
            }
        }
        SegmentIndex { cell, cells }
    }

    /// Distance from `p` to the nearest indexed segment, or `cap` if none is nearer. Rings
    /// of cells are searched outward until the nearest hit is closer than the next ring.
    pub(crate) fn distance(&self, p: V2, cap: f64) -> f64 {
        let r = (cap / self.cell).ceil().clamp(0.0, 1000.0) as i64;
        let (cx, cy) = ((p.x / self.cell).floor() as i64, (p.y / self.cell).floor() as i64);
        let mut best = cap;
        for ring in 0..=r {
            for x in cx - ring..=cx + ring {
                for y in cy - ring..=cy + ring {
                    if (x - cx).abs() != ring && (y - cy).abs() != ring {
                        continue;
                    }
                    if let Some(v) = self.cells.get(&(x, y)) {
                        for &(a, b) in v {
                            best = best.min(to_segment(p, a, b).0);
                        }
                    }
                }
            }
            // everything in the rings beyond is at least `ring` cells away
            if best <= ring as f64 * self.cell {
                break;
            }
        }
        best
    }
}

/// Points along a polyline: its vertices and points every `step` m between them.
pub(crate) fn samples(a: &[V2], step: f64) -> Vec<V2> {
    let mut out = Vec::new();
    for w in a.windows(2) {
        let n = ((w[0].dist(w[1]) / step).ceil() as usize).clamp(1, 100_000);
        out.extend((0..n).map(|k| w[0].lerp(w[1], k as f64 / n as f64)));
    }
    out.extend(a.last().copied());
    out
}

/// Largest distance from a point of `a` (its vertices and points every `step` m between
/// them) to the polyline `b`, the one-sided Hausdorff distance (sampled), capped at `cap`.
pub(crate) fn one_sided_distance(a: &[V2], b: &[V2], step: f64, cap: f64) -> f64 {
    // cells about half a segment long: few cells per segment, few segments per cell
    let mean = length(b) / b.len().max(2).saturating_sub(1) as f64;
    let index = SegmentIndex::new([b], (0.5 * mean).max(cap).max(0.5));
    samples(a, step).into_iter().map(|p| index.distance(p, cap)).fold(0.0, f64::max)
}

/// Whether two segments properly cross (shared end points do not count).
pub(crate) fn segments_cross(a: V2, b: V2, c: V2, d: V2) -> bool {
    let d1 = b.sub(a).cross(c.sub(a));
    let d2 = b.sub(a).cross(d.sub(a));
    let d3 = d.sub(c).cross(a.sub(c));
    let d4 = d.sub(c).cross(b.sub(c));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances() {
        let line = [V2::new(0.0, 0.0), V2::new(10.0, 0.0)];
        assert_eq!(to_polyline(V2::new(5.0, 2.0), &line), 2.0);
        assert_eq!(to_polyline(V2::new(13.0, 4.0), &line), 5.0);
        let other = [V2::new(0.0, 1.0), V2::new(10.0, 1.5)];
        assert!((one_sided_distance(&other, &line, 0.5, 5.0) - 1.5).abs() < 1e-12);
        assert_eq!(one_sided_distance(&other, &line, 0.5, 1.0), 1.0);
        assert!(segments_cross(V2::new(0.0, -1.0), V2::new(0.0, 1.0), V2::new(-1.0, 0.0), V2::new(1.0, 0.0)));
        assert!(!segments_cross(V2::new(0.0, 0.0), V2::new(1.0, 0.0), V2::new(1.0, 0.0), V2::new(2.0, 1.0)));
    }

    #[test]
    fn dedup_keeps_the_end() {
        let line = [V2::new(0.0, 0.0), V2::new(0.0, 0.0), V2::new(1.0, 0.0), V2::new(1.0 + 1e-12, 0.0)];
        let d = dedup(&line, 1e-9);
        assert_eq!(d.len(), 2);
        assert_eq!(d[1].x, 1.0 + 1e-12);
    }
}

//! Straight segments between vertices. Each vertex has a heading — the one its position gives
//! explicitly, else the direction of the segment leaving it (the last vertex: of the last
//! segment) — and the heading between vertices is interpolated as esmini's
//! PolyLineBase::EvaluateSegmentByLocalS does: with corner interpolation (esmini's for the
//! `position` following mode and trajectory positions) it holds the vertex's heading and
//! turns linearly across a corner over min(2 m, half the segment's length) on each side,
//! half the turn on either side of the vertex, the last segment turning to the final
//! vertex's heading over its last such stretch; with segment interpolation (the `follow`
//! mode) it turns linearly from one vertex's heading to the next over the whole segment.

use crate::angle;
use crate::pose::PathPoint;
use crate::ESMINI_SMALL;

/// Half-width of esmini's corner blending (at most half the segment).
const CORNER_RADIUS: f64 = 2.0;

/// How the heading is interpolated between vertices (esmini's PolyLineBase::InterpolationMode).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Interpolation {
    /// Along each segment's vertex heading, turning only across corners.
    #[default]
    Corner,
    /// Linearly from vertex to vertex over each whole segment.
    Segment,
    /// Not at all: each segment keeps the heading of the vertex it starts at (esmini's
    /// INTERPOLATE_NONE, the mode of a polyline no FollowTrajectoryAction has set, e.g. one
    /// read for a TrajectoryPosition).
    None,
}

#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Polyline {
    /// (x, y, z, s) of each vertex; s strictly increasing.
    pts: Vec<[f64; 4]>,
    /// Heading of segment i (pts[i] → pts[i+1]).
    headings: Vec<f64>,
    /// Heading of vertex i: given explicitly, else that of the segment leaving it.
    vertex_headings: Vec<f64>,
    /// The last segment returns to the first vertex: corners wrap.
    closed: bool,
    pub(crate) mode: Interpolation,
}

impl Polyline {
    /// `pts` are (x, y, z) without zero-length segments, at least two of them; `explicit`
    /// the heading a vertex's position gives, if any (missing entries: none).
    pub(crate) fn new(xyz: &[[f64; 3]], explicit: &[Option<f64>], closed: bool) -> Polyline {
        let mut pts = Vec::with_capacity(xyz.len());
        let mut headings = Vec::with_capacity(xyz.len());
        let mut s = 0.0;
        for (i, p) in xyz.iter().enumerate() {
            if let Some(prev) = i.checked_sub(1).and_then(|j| xyz.get(j)) {
                s += (p[0] - prev[0]).hypot(p[1] - prev[1]);
                headings.push(angle::normalize((p[1] - prev[1]).atan2(p[0] - prev[0])));
            }
            pts.push([p[0], p[1], p[2], s]);
        }
        let last = xyz.len().saturating_sub(1);
        let vertex_headings = (0..xyz.len())
            .map(|i| {
                let own = if closed && i == last { headings.first() } else { headings.get(i.min(headings.len().saturating_sub(1))) };
                let implicit = own.copied().unwrap_or(0.0);
                let given = if closed && i == last { explicit.first() } else { explicit.get(i) };
                given.copied().flatten().map_or(implicit, angle::normalize)
            })
            .collect();
        Polyline { pts, headings, vertex_headings, closed, mode: Interpolation::Corner }
    }

    pub(crate) fn length(&self) -> f64 {
        self.pts.last().map_or(0.0, |p| p[3])
    }

    /// The segment that holds `s` (the last one at and past the end).
    fn segment_at(&self, s: f64) -> usize {
        let nseg = self.headings.len();
        self.pts.partition_point(|p| p[3] <= s).saturating_sub(1).min(nseg.saturating_sub(1))
    }

    /// The heading of the first segment that reaches `s` within esmini's SMALL_NUMBER
    /// (PolyLineBase::Evaluate's search): at a vertex, the segment that ends there; at and past
    /// the end, the last.
    pub(crate) fn heading_of_segment_reaching(&self, s: f64) -> f64 {
        let nseg = self.headings.len();
        let i = self.pts.get(1..).map_or(0, |rest| rest.partition_point(|p| p[3] + ESMINI_SMALL < s));
        self.heading(Some(i.min(nseg.saturating_sub(1)))).unwrap_or(0.0)
    }

    /// The segments before and after segment `i` (across the end of a closed polyline).
    fn neighbours(&self, i: usize) -> (Option<usize>, Option<usize>) {
        let nseg = self.headings.len();
        let prev = if i > 0 {
            Some(i - 1)
        } else if self.closed {
            Some(nseg - 1)
        } else {
            None
        };
        let next = if i + 1 < nseg {
            Some(i + 1)
        } else if self.closed {
            Some(0)
        } else {
            None
        };
        (prev, next)
    }

    fn heading(&self, i: Option<usize>) -> Option<f64> {
        i.and_then(|i| self.headings.get(i)).copied()
    }

    /// Pitch of segment `i`: −atan2(dz, horizontal length), nose down positive (esmini's
    /// PolyLineShape::CalculatePolyLine).
    fn segment_pitch(&self, i: usize) -> Option<f64> {
        let (a, b) = (self.pts.get(i)?, self.pts.get(i + 1)?);
        Some(-(b[2] - a[2]).atan2(b[3] - a[3]))
    }

    /// Pitch at `s`, blended across corners as the heading is (esmini interpolates a
    /// trajectory's pitch with the same corner weights).
    pub(crate) fn pitch(&self, s: f64) -> f64 {
        let i = self.segment_at(s);
        let (Some(a), Some(b), Some(p)) = (self.pts.get(i), self.pts.get(i + 1), self.segment_pitch(i)) else { return 0.0 };
        let len = b[3] - a[3];
        let local = (s - a[3]).clamp(0.0, len);
        let r = CORNER_RADIUS.min(len / 2.0);
        let (prev, next) = self.neighbours(i);
        if r > 0.0 && local < r {
            if let Some(pp) = prev.and_then(|j| self.segment_pitch(j)) {
                return pp + (r + local) / (2.0 * r) * angle::diff(p, pp);
            }
        } else if r > 0.0 && local > len - r {
            if let Some(pn) = next.and_then(|j| self.segment_pitch(j)) {
                let w = (r + (len - local)) / (2.0 * r);
                return p + (1.0 - w) * angle::diff(pn, p);
            }
        }
        p
    }

    /// Heading of the segment that holds `s` (the last one at and past the end).
    pub(crate) fn segment_heading(&self, s: f64) -> f64 {
        let i = self.segment_at(s);
        self.heading(Some(i)).unwrap_or(0.0)
    }

    pub(crate) fn eval(&self, s: f64) -> PathPoint {
        let nseg = self.headings.len();
        let i = self.pts.partition_point(|p| p[3] <= s).saturating_sub(1).min(nseg.saturating_sub(1));
        let (Some(a), Some(b), Some(&h), Some(&hn)) = (self.pts.get(i), self.pts.get(i + 1), self.vertex_headings.get(i), self.vertex_headings.get(i + 1))
        else {
            let p = self.pts.first().copied().unwrap_or([0.0; 4]);
            return PathPoint { s, x: p[0], y: p[1], z: p[2], heading: 0.0, curvature: 0.0 };
        };
        let len = b[3] - a[3];
        let local = (s - a[3]).clamp(0.0, len);
        let u = if len > 0.0 { local / len } else { 0.0 };
        let lerp = |k: usize| a[k] + u * (b[k] - a[k]);
        let (heading, curvature) = match self.mode {
            Interpolation::Segment => {
                let turn = angle::diff(hn, h);
                (h + u * turn, if len > 0.0 { turn / len } else { 0.0 })
            }
            Interpolation::Corner => self.corner_heading(i, h, hn, len, local),
            Interpolation::None => (h, 0.0),
        };
        PathPoint { s, x: lerp(0), y: lerp(1), z: lerp(2), heading: angle::normalize(heading), curvature }
    }

    /// Corner interpolation on segment `i` (vertex headings `h`, `hn`) at `local` of `len`.
    fn corner_heading(&self, i: usize, h: f64, hn: f64, len: f64, local: f64) -> (f64, f64) {
        let nseg = self.headings.len();
        let r = CORNER_RADIUS.min(len / 2.0);
        let (prev, _) = self.neighbours(i);
        // Same precedence as esmini: the corner at the start wins when both overlap.
        if r > 0.0 && local < r {
            return match prev.and_then(|j| self.vertex_headings.get(j)) {
                Some(&hp) => {
                    let turn = angle::diff(h, hp);
                    (hp + (r + local) / (2.0 * r) * turn, turn / (2.0 * r))
                }
                None => (h, 0.0),
            };
        }
        if r > 0.0 && local > len - r {
            let turn = angle::diff(hn, h);
            // The last segment of an open polyline turns to the final vertex's heading over
            // its last stretch alone.
            let last = i + 1 >= nseg && !self.closed;
            let (w, width) = if last { ((len - local) / r, r) } else { ((r + (len - local)) / (2.0 * r), 2.0 * r) };
            return (h + (1.0 - w) * turn, turn / width);
        }
        (h, 0.0)
    }
}

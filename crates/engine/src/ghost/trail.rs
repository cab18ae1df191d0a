//! The trail a ghost leaves: its positions and speeds sampled every 0.2 s of simulation time,
//! as a polyline measured by 2D arc length. FollowGhostController looks along it for the
//! point nearest to the follower and for points a look-ahead distance further on. Sampling
//! follows esmini: a vertex when more than 0.2 s passed since the last one, none while the
//! ghost stands still, and after a standstill the last vertex is repeated 0.2 s before the new
//! one so the speed ramps up along the trail from there.

/// Time between trail samples, s.
const SAMPLE_TIME: f64 = 0.2;
/// esmini's SMALL_NUMBER (1e-6, CommonMini.hpp) in `prepareGroundTruth`'s sampling rule: speeds
/// at or below it stand still, and a sample is due once `ghost_trail_dt - SMALL_NUMBER`
/// passed, so a step whose accumulated clock falls a hair short of 0.2 s still samples.
const TOLERANCE: f64 = crate::dynamics::ESMINI_SMALL_NUMBER;
/// A trail never holds more vertices than this (hostile input: hours of simulation).
const MAX_VERTICES: usize = 1 << 20;

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TrailPoint {
    pub x: f64,
    pub y: f64,
    /// Arc length from the first vertex, m.
    pub s: f64,
    pub time: f64,
    pub speed: f64,
}

#[derive(Debug, Clone, Default, PartialEq)]
pub(crate) struct Trail {
    pub vertices: Vec<TrailPoint>,
}

impl Trail {
    /// Offer the ghost's state at `time`; kept when the sampling rule says so.
    pub(crate) fn sample(&mut self, time: f64, x: f64, y: f64, speed: f64) {
        if self.vertices.len() >= MAX_VERTICES {
            return;
        }
        let Some(last) = self.vertices.last().copied() else {
            self.push(x, y, time, speed);
            return;
        };
        if time - last.time <= SAMPLE_TIME - TOLERANCE || (last.speed.abs() <= TOLERANCE && speed.abs() <= TOLERANCE) {
            return;
        }
        if time - last.time > 2.0 * SAMPLE_TIME - TOLERANCE {
            self.vertices.push(TrailPoint { time: time - SAMPLE_TIME, ..last });
        }
        self.push(x, y, time, speed);
    }

    fn push(&mut self, x: f64, y: f64, time: f64, speed: f64) {
        let s = self.vertices.last().map_or(0.0, |p| p.s + (x - p.x).hypot(y - p.y));
        self.vertices.push(TrailPoint { x, y, s, time, speed });
    }

    /// The point of segment `i` at `local_s` from its start (clamped to the segment), every
    /// field interpolated linearly; the vertex itself for `i` at or past the last one
    /// (esmini's `PolyLineBase::EvaluateSegmentByLocalS`).
    fn on_segment(&self, i: usize, local_s: f64) -> Option<TrailPoint> {
        let a = *self.vertices.get(i)?;
        let Some(b) = self.vertices.get(i + 1).copied() else { return Some(a) };
        let len = (b.s - a.s).max(TOLERANCE);
        let w = local_s.clamp(0.0, len) / len;
        let mix = |p: f64, q: f64| (1.0 - w) * p + w * q;
        Some(TrailPoint { x: mix(a.x, b.x), y: mix(a.y, b.y), s: mix(a.s, b.s), time: mix(a.time, b.time), speed: mix(a.speed, b.speed) })
    }

    /// Distance from (x, y) to segment `i` and the arc length along it of the nearest point,
    /// as esmini's `FindClosestPoint` measures them: the projection on the segment's line
    /// when it falls between the end points (`PointInBetweenVectorEndpoints` decides by x, or
    /// by y for a steep segment), else the distance along and across to the nearer end.
    fn segment_distance(&self, i: usize, x: f64, y: f64) -> (f64, f64) {
        let (a, b) = (self.vertices[i], self.vertices[i + 1]);
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        if dx.abs() < TOLERANCE && dy.abs() < TOLERANCE {
            // No line to project on (`ProjectPointOnLine2D` fails): the first end point.
            return ((x - a.x).hypot(y - a.y), b.s - a.s);
        }
        let k = (dy * (x - a.x) - dx * (y - a.y)) / (dy * dy + dx * dx);
        let (px, py) = (x - k * dy, y + k * dx);
        let across = (x - px).hypot(y - py);
        let (p, p1, p2) = if dx.abs() < dy.abs() { (py, a.y, b.y) } else { (px, a.x, b.x) };
        let norm = (p - p1) / (p2 - p1);
        let inside = if p2 > p1 { !(p < p1 || p > p2) } else { !(p > p1 || p < p2) };
        if inside {
            (across, norm * (b.s - a.s))
        } else if norm < 0.0 {
            (across.hypot((px - a.x).hypot(py - a.y)), 0.0)
        } else {
            (across.hypot((px - b.x).hypot(py - b.y)), b.s - a.s)
        }
    }

    /// The trail point nearest to (x, y) and its segment, searched as esmini's
    /// `PolyLineBase::FindClosestPoint` does: from segment `start` forwards; when `start` is
    /// past 0, the first segment farther than the best so far turns the search back from
    /// `start`, and the next farther one ends it (a local minimum around `start`). A `start`
    /// beyond the trail (it was reset) searches from 0. `None` when no segment was looked at:
    /// fewer than two vertices, or `start` on the last vertex (where the previous point ahead
    /// ran off the trail's end) — esmini then keeps the old arc length.
    pub(crate) fn closest(&self, x: f64, y: f64, start: usize) -> Option<(TrailPoint, usize)> {
        let n = self.vertices.len();
        let start = if start + 1 > n { 0 } else { start };
        let (mut i, mut forward) = (start, true);
        let mut best: Option<(f64, usize, f64)> = None;
        while i + 1 < n {
            let (dist, local) = self.segment_distance(i, x, y);
            if best.is_none_or(|(d, _, _)| dist < d + TOLERANCE) {
                best = Some((dist, i, local));
            } else if start > 0 {
                if !forward {
                    break;
                }
                i = start;
                forward = false;
            }
            if forward {
                i += 1;
            } else if i > 0 {
                i -= 1;
            } else {
                break;
            }
        }
        let (_, i, local) = best?;
        Some((self.on_segment(i, local)?, i))
    }

    /// The point at arc length `s` and its segment, as esmini's `PolyLineBase::Evaluate`
    /// finds it from segment `start`: at or past the end (within 1e-6 m) the last vertex and
    /// index; otherwise forwards or backwards to the first segment whose start lies more than
    /// 1e-6 m before `s` (so a point on a vertex is the end of the segment before it).
    /// `None` on an empty trail.
    pub(crate) fn at_s(&self, s: f64, start: usize) -> Option<(TrailPoint, usize)> {
        let n = self.vertices.len();
        let last = *self.vertices.last()?;
        if s > last.s - TOLERANCE {
            return Some((last, n - 1));
        }
        let v = &self.vertices;
        let mut i = start.min(n - 1);
        if s > v[i].s + TOLERANCE {
            while i + 1 < n && s > v[i + 1].s + TOLERANCE {
                i += 1;
            }
        } else {
            while i > 0 && s < v[i].s + TOLERANCE {
                i -= 1;
            }
        }
        let p = self.on_segment(i, s - v[i].s)?;
        Some((TrailPoint { s, ..p }, i))
    }

    /// Where the ghost was at `time` and its segment, as esmini's `FindPointAtTime`: the arc
    /// length by time between the samples around `time` (`Time2S`, searching from segment
    /// `start`; the first or last vertex outside the sampled span, within 1e-6 s), then the
    /// point at that arc length (`at_s`). `None` on an empty trail.
    pub(crate) fn at_time(&self, time: f64, start: usize) -> Option<(TrailPoint, usize)> {
        let v = &self.vertices;
        let n = v.len();
        let first = *v.first()?;
        let (s, i) = if n == 1 || time < first.time + TOLERANCE {
            (0.0, 0)
        } else if time > v[n - 1].time - TOLERANCE {
            (v[n - 1].s, n - 1)
        } else {
            let mut i = start.min(n - 1);
            if time < v[i].time - TOLERANCE {
                i = i.saturating_sub(1);
                while i > 0 && time <= v[i].time - TOLERANCE {
                    i -= 1;
                }
            } else {
                while i + 1 < n - 1 && time >= v[i + 1].time - TOLERANCE {
                    i += 1;
                }
            }
            let w = (time - v[i].time) / (v[i + 1].time - v[i].time);
            ((v[i].s + w * (v[i + 1].s - v[i].s)).max(0.0), i)
        };
        self.at_s(s, i)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Steps of 1/8 s (exact in binary, so the 0.2 s rule does not hinge on rounding).
    fn straight(n: usize, v: f64) -> Trail {
        let mut t = Trail::default();
        for k in 0..=n {
            let time = k as f64 * 0.125;
            t.sample(time, v * time, 0.0, v);
        }
        t
    }

    #[test]
    fn samples_every_fifth_of_a_second() {
        let t = straight(8, 10.0);
        // 0, then the first step more than 0.2 s after the last sample: 0.25, 0.5, 0.75, 1.
        assert_eq!(t.vertices.len(), 5);
        assert_eq!(t.vertices[1].time, 0.25);
        assert!((t.vertices[4].s - 10.0).abs() < 1e-12);
    }

    #[test]
    fn an_accumulated_clock_a_hair_short_of_the_interval_still_samples() {
        // esmini's clock adds 0.01 s a step from −3 s: some intervals come out at
        // 0.19999999999999x s, and esmini samples them (its tolerance is 1e-6 s).
        let mut t = Trail::default();
        let mut clock = -3.0_f64;
        for _ in 0..1000 {
            t.sample(clock, clock * 10.0, 0.0, 10.0);
            clock += 0.01;
        }
        for w in t.vertices.windows(2) {
            assert!((w[1].time - w[0].time - 0.2).abs() < 1e-9, "{} → {}", w[0].time, w[1].time);
        }
    }

    #[test]
    fn nothing_is_sampled_while_standing_still() {
        let mut t = Trail::default();
        for k in 0..100 {
            t.sample(k as f64 * 0.01, 0.0, 0.0, 0.0);
        }
        assert_eq!(t.vertices.len(), 1);
        // Moving again: the old vertex is repeated 0.2 s before the new one.
        t.sample(1.0, 0.5, 0.0, 1.0);
        assert_eq!(t.vertices.len(), 3);
        assert!((t.vertices[1].time - 0.8).abs() < 1e-12 && t.vertices[1].x == 0.0);
    }

    #[test]
    fn the_nearest_point_search_is_local_around_its_start_as_esmini_s() {
        // Vertices at x = 0, 2.5, 5, 7.5, 10; the point (3, 1) is nearest to segment 1.
        let t = straight(8, 10.0);
        // From segment 2: forwards it gets farther, so back from 2 to the local minimum.
        let (p, i) = t.closest(3.0, 1.0, 2).expect("segments searched");
        assert!((p.x - 3.0).abs() < 1e-9 && i == 1, "{p:?} {i}");
        // From the last segment: nothing farther was met, so its start is kept.
        let (p, i) = t.closest(3.0, 1.0, 3).expect("segments searched");
        assert!((p.x - 7.5).abs() < 1e-9 && i == 3, "{p:?} {i}");
        // From the last vertex no segment is searched (esmini keeps the old arc length).
        assert!(t.closest(3.0, 1.0, 4).is_none());
        // A point ahead beyond the end is the last vertex, whose index is the last vertex's.
        let (q, j) = t.at_s(11.0, 0).expect("trail has vertices");
        assert!((q.x - 10.0).abs() < 1e-12 && j == 4, "{q:?} {j}");
        // Exactly on a vertex it is the end of the segment before it.
        assert_eq!(t.at_s(5.0, 3).map(|(_, j)| j), Some(1));
    }

    #[test]
    fn closest_point_and_point_ahead() {
        let t = straight(8, 10.0);
        let (p, i) = t.closest(3.0, 1.0, 0).expect("trail has segments");
        assert!((p.x - 3.0).abs() < 1e-9 && p.y.abs() < 1e-12 && (p.s - 3.0).abs() < 1e-9);
        assert_eq!(i, 1);
        let (q, _) = t.at_s(p.s + 2.5, i).expect("trail has vertices");
        assert!((q.x - 5.5).abs() < 1e-9 && (q.speed - 10.0).abs() < 1e-12);
        // Beyond the end: the last vertex.
        let (r, _) = t.at_s(100.0, 0).expect("trail has vertices");
        assert!((r.x - 10.0).abs() < 1e-12);
        // Where the ghost was at 0.6 s: 6 m, between the samples at 0.5 and 0.75 s.
        let (w, _) = t.at_time(0.6, 0).expect("trail has vertices");
        assert!((w.x - 6.0).abs() < 1e-9);
    }
}

//! The trail a ghost leaves: its positions and speeds sampled every 0.2 s of simulation time,
//! as a polyline measured by 2D arc length. FollowGhostController looks along it for the
//! point nearest to the follower and for points a look-ahead distance further on. Sampling
//! follows esmini: a vertex when more than 0.2 s passed since the last one, none while the
//! ghost stands still, and after a standstill the last vertex is repeated 0.2 s before the new
//! one so the speed ramps up along the trail from there.

/// Time between trail samples, s.
const SAMPLE_TIME: f64 = 0.2;
/// Shortest segment length, m.
const SMALL: f64 = 1e-10;
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
    /// field interpolated linearly; the last vertex itself for `i` at or past the last one.
    fn on_segment(&self, i: usize, local_s: f64) -> Option<TrailPoint> {
        let a = *self.vertices.get(i)?;
        let Some(b) = self.vertices.get(i + 1).copied() else { return Some(a) };
        let len = (b.s - a.s).max(SMALL);
        let w = local_s.clamp(0.0, len) / len;
        let mix = |p: f64, q: f64| (1.0 - w) * p + w * q;
        Some(TrailPoint { x: mix(a.x, b.x), y: mix(a.y, b.y), s: mix(a.s, b.s), time: mix(a.time, b.time), speed: mix(a.speed, b.speed) })
    }

    /// The trail point nearest to (x, y), searching the segments from `start` on, and the
    /// index of its segment. Beyond a segment's ends the distance to the end point counts
    /// along and across the segment. `None` with fewer than two vertices.
    pub(crate) fn closest(&self, x: f64, y: f64, start: usize) -> Option<(TrailPoint, usize)> {
        let n = self.vertices.len();
        // After the trail was reset the old index may lie beyond it.
        let start = if start + 1 > n { 0 } else { start };
        let mut best: Option<(f64, usize, f64)> = None;
        for i in start..n.saturating_sub(1) {
            let (a, b) = (self.vertices[i], self.vertices[i + 1]);
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let len2 = dx * dx + dy * dy;
            let u = if len2 > 0.0 { ((x - a.x) * dx + (y - a.y) * dy) / len2 } else { 0.0 };
            let (px, py) = (a.x + u * dx, a.y + u * dy);
            let across = (x - px).hypot(y - py);
            let seg = b.s - a.s;
            let (dist, local) = if u < 0.0 {
                let along = -u * len2.sqrt();
                (across.hypot(along), 0.0)
            } else if u > 1.0 {
                let along = (u - 1.0) * len2.sqrt();
                (across.hypot(along), seg)
            } else {
                (across, u * seg)
            };
            if best.is_none_or(|(d, _, _)| dist < d) {
                best = Some((dist, i, local));
            }
        }
        let (_, i, local) = best?;
        Some((self.on_segment(i, local)?, i))
    }

    /// The point at arc length `s` (the last vertex beyond the end), searching from segment
    /// `start`, and its segment index. `None` on an empty trail.
    pub(crate) fn at_s(&self, s: f64, start: usize) -> Option<(TrailPoint, usize)> {
        let last = *self.vertices.last()?;
        if s > last.s {
            let i = self.vertices.len() - 1;
            return Some((TrailPoint { s, ..last }, i));
        }
        let mut i = start.min(self.vertices.len() - 1);
        while i + 1 < self.vertices.len() && self.vertices[i + 1].s <= s {
            i += 1;
        }
        let p = self.on_segment(i, s - self.vertices[i].s)?;
        Some((TrailPoint { s, ..p }, i))
    }

    /// Where the ghost was at `time` (interpolated between samples; the first or last vertex
    /// outside the sampled span), searching from segment `start`, and its segment index.
    pub(crate) fn at_time(&self, time: f64, start: usize) -> Option<(TrailPoint, usize)> {
        let first = *self.vertices.first()?;
        let n = self.vertices.len();
        if time <= first.time {
            return Some((first, 0));
        }
        let mut i = if self.vertices.get(start).is_some_and(|v| v.time <= time) { start } else { 0 };
        while i + 1 < n && self.vertices[i + 1].time <= time {
            i += 1;
        }
        let a = self.vertices[i];
        let Some(b) = self.vertices.get(i + 1) else { return Some((a, i)) };
        let span = b.time - a.time;
        let w = if span > SMALL { (time - a.time) / span } else { 0.0 };
        self.on_segment(i, w * (b.s - a.s)).map(|p| (p, i))
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

//! The arc-length-parameterised path every shape becomes.

use crate::nurbs_path::NurbsPath;
use crate::polyline::Polyline;
use crate::pose::PathPoint;
use crate::sampled::Sampled;
use crate::spiral::Spiral;
use crate::time_table::TimeTable;

#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Curve {
    Polyline(Polyline),
    /// Consecutive clothoid segments with the path s where each starts.
    Spirals(Vec<(f64, Spiral)>),
    Nurbs(NurbsPath),
    /// A curve as esmini's one-metre polyline (ClothoidSpline).
    Sampled(Sampled),
}

/// A trajectory as a path: `pose_at(s)` for s in [0, length], optional time stamps.
/// A closed path wraps s (and time, lap by lap) around.
#[derive(Debug, Clone, PartialEq)]
pub struct Path {
    pub(crate) curve: Curve,
    pub(crate) length: f64,
    pub(crate) closed: bool,
    pub(crate) times: Option<TimeTable>,
    /// Things a user should know that did not stop the path being built
    /// (duplicate vertices dropped, partial time stamps ignored, …).
    pub warnings: Vec<String>,
}

impl Path {
    pub fn length(&self) -> f64 {
        self.length
    }
    pub fn is_closed(&self) -> bool {
        self.closed
    }
    /// Whether the shape carries time stamps.
    pub fn is_timed(&self) -> bool {
        self.times.is_some()
    }
    pub fn time_table(&self) -> Option<&TimeTable> {
        self.times.as_ref()
    }

    /// s brought into [0, length]: wrapped on a closed path, clamped on an open one.
    pub fn normalize_s(&self, s: f64) -> f64 {
        if !s.is_finite() {
            return if s == f64::INFINITY && !self.closed { self.length } else { 0.0 };
        }
        if self.closed && self.length > 0.0 {
            let r = s.rem_euclid(self.length);
            if r >= self.length {
                0.0
            } else {
                r
            }
        } else {
            s.clamp(0.0, self.length)
        }
    }

    /// Whether the shape is a polyline (esmini times its segments by constant accelerations in
    /// the `follow` mode; the other shapes' time runs linearly with their length).
    pub fn is_polyline(&self) -> bool {
        matches!(self.curve, Curve::Polyline(_))
    }

    /// How a polyline's heading is interpolated between its vertices (other shapes keep theirs).
    pub fn set_interpolation(&mut self, mode: crate::polyline::Interpolation) {
        if let Curve::Polyline(p) = &mut self.curve {
            p.mode = mode;
        }
    }

    /// Position, heading and curvature at arc length `s` (see [`Path::normalize_s`]).
    pub fn pose_at(&self, s: f64) -> PathPoint {
        self.eval(self.normalize_s(s))
    }

    /// The point at the end of the path. On a closed path [`Path::pose_at`] wraps the length
    /// to the start, which is a different point when the shape itself does not return there
    /// (a NURBS marked closed); an entity that finishes the path stays at its end (esmini).
    pub fn end_pose(&self) -> PathPoint {
        self.eval(self.length)
    }

    /// The direction of the path itself at `s`, without a polyline's corner blending: the
    /// heading of the polyline segment that holds `s` (esmini's `h_true` of a trajectory
    /// vertex), the tangent of the other shapes.
    pub fn true_heading_at(&self, s: f64) -> f64 {
        let s = self.normalize_s(s);
        match &self.curve {
            Curve::Polyline(p) => p.segment_heading(s),
            _ => self.eval(s).heading,
        }
    }

    /// [`Path::true_heading_at`] as esmini's trajectory holds it after evaluating `s`
    /// (`RMTrajectory::GetHTrue`): on a polyline exactly at a vertex, the heading of the segment
    /// that ends there.
    pub fn true_heading_reaching(&self, s: f64) -> f64 {
        let s = self.normalize_s(s);
        match &self.curve {
            Curve::Polyline(p) => p.heading_of_segment_reaching(s),
            _ => self.eval(s).heading,
        }
    }

    /// Pitch at `s` from the vertices' heights: a polyline's, blended across corners; 0 for
    /// the other shapes (their points carry no heights of their own).
    pub fn pitch_at(&self, s: f64) -> f64 {
        match &self.curve {
            Curve::Polyline(p) => p.pitch(self.normalize_s(s)),
            _ => 0.0,
        }
    }

    fn eval(&self, s: f64) -> PathPoint {
        let mut p = match &self.curve {
            Curve::Polyline(p) => p.eval(s),
            Curve::Nurbs(n) => n.eval(s),
            Curve::Sampled(p) => p.eval(s),
            Curve::Spirals(list) => {
                let i = list.partition_point(|(s0, _)| *s0 <= s).saturating_sub(1);
                match list.get(i) {
                    Some((s0, sp)) => sp.eval(s - s0),
                    None => PathPoint { s, x: 0.0, y: 0.0, z: 0.0, heading: 0.0, curvature: 0.0 },
                }
            }
        };
        p.s = s;
        p
    }

    /// Trajectory time at arc length `s` (None when untimed). On a closed path s beyond the
    /// length counts further laps of (end time − start time).
    pub fn time_at(&self, s: f64) -> Option<f64> {
        let tt = self.times.as_ref()?;
        let (laps, local) = self.laps(s);
        Some(tt.time_at(local) + laps * (tt.end_time() - tt.start_time()))
    }

    /// Arc length reached at trajectory time `t` (None when untimed). Before the first stamp
    /// it is 0; after the last, the end (open) or further laps (closed, when the lap takes time).
    pub fn s_at_time(&self, t: f64) -> Option<f64> {
        let tt = self.times.as_ref()?;
        let lap = tt.end_time() - tt.start_time();
        if self.closed && lap > 0.0 && t > tt.end_time() && t.is_finite() {
            let laps = ((t - tt.start_time()) / lap).floor();
            let local = t - laps * lap;
            return Some(tt.s_at_time(local) + laps * self.length);
        }
        Some(tt.s_at_time(t))
    }

    /// First and last time stamps.
    pub fn time_range(&self) -> Option<(f64, f64)> {
        self.times.as_ref().map(|t| (t.start_time(), t.end_time()))
    }

    fn laps(&self, s: f64) -> (f64, f64) {
        if self.closed && self.length > 0.0 && s.is_finite() {
            let laps = (s / self.length).floor().max(0.0);
            (laps, self.normalize_s(s))
        } else {
            (0.0, self.normalize_s(s))
        }
    }

    /// Arc length of the point of the path nearest to (x, y) (coarse scan, then refined).
    pub fn closest_s(&self, x: f64, y: f64) -> f64 {
        let n = ((self.length / 0.5).ceil() as usize).clamp(1, 200_000);
        let d2 = |s: f64| {
            let p = self.pose_at(s);
            (p.x - x).powi(2) + (p.y - y).powi(2)
        };
        let step = self.length / n as f64;
        let mut best = (0.0, d2(0.0));
        for i in 1..=n {
            let s = i as f64 * step;
            let d = d2(s);
            if d < best.1 {
                best = (s, d);
            }
        }
        // Golden-section refinement inside the best bracket.
        let (mut a, mut b) = ((best.0 - step).max(0.0), (best.0 + step).min(self.length));
        let g = 0.618_033_988_749_894_9;
        for _ in 0..60 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if d2(c) < d2(d) {
                b = d;
            } else {
                a = c;
            }
        }
        let s = 0.5 * (a + b);
        if d2(s) < best.1 {
            s
        } else {
            best.0
        }
    }
}

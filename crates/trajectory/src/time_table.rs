//! Time stamps along a path: piecewise-linear s ↔ t, both non-decreasing.

use crate::error::Error;

/// (s, t) pairs with s and t non-decreasing. Equal s with rising t is a stop (the entity
/// waits at that point); equal t with rising s would be a jump and is kept as given.
#[derive(Debug, Clone, PartialEq)]
pub struct TimeTable {
    points: Vec<(f64, f64)>,
}

impl TimeTable {
    /// Build from (s, t) pairs; `shape` names the shape in errors.
    pub fn new(shape: &'static str, points: Vec<(f64, f64)>) -> Result<TimeTable, Error> {
        if points.is_empty() {
            return Err(Error::TooFew { shape, what: "time stamps", needed: 1, found: 0 });
        }
        for (i, &(s, t)) in points.iter().enumerate() {
            if !t.is_finite() {
                return Err(Error::BadNumber { shape, what: format!("time stamp {i}"), constraint: "", value: t });
            }
            if !s.is_finite() {
                return Err(Error::BadNumber { shape, what: format!("arc length {i}"), constraint: "", value: s });
            }
        }
        for (i, w) in points.windows(2).enumerate() {
            if let [a, b] = w {
                if b.1 < a.1 {
                    return Err(Error::NotMonotone { shape, what: "time stamps", index: i + 1 });
                }
                if b.0 < a.0 {
                    return Err(Error::NotMonotone { shape, what: "arc lengths", index: i + 1 });
                }
            }
        }
        Ok(TimeTable { points })
    }

    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }
    pub fn start_time(&self) -> f64 {
        self.points.first().map_or(0.0, |p| p.1)
    }
    pub fn end_time(&self) -> f64 {
        self.points.last().map_or(0.0, |p| p.1)
    }

    /// Time at arc length `s` (clamped to the table); at a stop, the time of arrival.
    pub fn time_at(&self, s: f64) -> f64 {
        let p = &self.points;
        let i = p.partition_point(|q| q.0 < s);
        match (i.checked_sub(1).and_then(|j| p.get(j)), p.get(i)) {
            (None, Some(b)) => b.1,
            (Some(a), None) => a.1,
            (Some(a), Some(b)) => lerp_by(a.0, b.0, s, a.1, b.1),
            (None, None) => 0.0,
        }
    }

    /// Arc length reached at time `t` (clamped to the table).
    pub fn s_at_time(&self, t: f64) -> f64 {
        let p = &self.points;
        let i = p.partition_point(|q| q.1 <= t);
        match (i.checked_sub(1).and_then(|j| p.get(j)), p.get(i)) {
            (None, Some(b)) => b.0,
            (Some(a), None) => a.0,
            (Some(a), Some(b)) => lerp_by(a.1, b.1, t, a.0, b.0),
            (None, None) => 0.0,
        }
    }
}

/// Value at `x` of the line through (x0, y0), (x1, y1); y0 when the interval is empty.
fn lerp_by(x0: f64, x1: f64, x: f64, y0: f64, y1: f64) -> f64 {
    let dx = x1 - x0;
    if dx <= 0.0 {
        return y0;
    }
    let a = ((x - x0) / dx).clamp(0.0, 1.0);
    y0 + a * (y1 - y0)
}

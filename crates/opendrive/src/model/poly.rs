//! Cubic polynomial records `a + b·ds + c·ds² + d·ds³` used all over OpenDRIVE
//! (elevation, superelevation, lane offset, lane width, lane border).

/// One cubic record valid from `s` (absolute road s, or `sOffset` inside a lane section)
/// until the next record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CubicRecord {
    pub s: f64,
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub d: f64,
}

impl CubicRecord {
    /// Value at `ds` past the record start.
    pub fn value(&self, ds: f64) -> f64 {
        self.a + ds * (self.b + ds * (self.c + ds * self.d))
    }
    /// First derivative at `ds` past the record start.
    pub fn slope(&self, ds: f64) -> f64 {
        self.b + ds * (2.0 * self.c + ds * 3.0 * self.d)
    }
}

/// The record in force at `s` in a list sorted by `s`: the last with `record.s <= s`,
/// or the first one when `s` lies before all of them.
pub fn record_at(records: &[CubicRecord], s: f64) -> Option<&CubicRecord> {
    let i = records.partition_point(|r| r.s <= s);
    records.get(i.saturating_sub(1))
}

/// Evaluate a piecewise cubic at `s`; 0 when there are no records.
pub fn piecewise_value(records: &[CubicRecord], s: f64) -> f64 {
    record_at(records, s).map_or(0.0, |r| r.value(s - r.s))
}

/// Derivative of a piecewise cubic at `s`; 0 when there are no records.
pub fn piecewise_slope(records: &[CubicRecord], s: f64) -> f64 {
    record_at(records, s).map_or(0.0, |r| r.slope(s - r.s))
}

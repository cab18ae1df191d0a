//! `<paramPoly3>`: u(p), v(p) cubics in the local frame with pRange `arcLength` (p ∈ [0, length])
//! or `normalized` (p ∈ [0, 1]).
//!
//! s is arc length in OpenDRIVE; p is only a parameter, so s is mapped to p through the
//! curve's arc-length table. The map is scaled so that s = length lands on p = p_max even if
//! the declared length and the true arc length differ slightly (the geometry then still ends
//! where the file says, where the next geometry starts).

use super::arc_length_table::{ArcLengthTable, CubicCurve};
use super::pose::CurvePose;

/// `pRange` of a paramPoly3.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PRange {
    ArcLength,
    Normalized,
}

/// A parametric cubic curve.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamPoly3 {
    pub u: [f64; 4],
    pub v: [f64; 4],
    pub p_range: PRange,
    pub length: f64,
    table: ArcLengthTable,
}

/// Pose of a cubic curve at parameter p.
pub(crate) fn pose_of(curve: &CubicCurve, p: f64) -> CurvePose {
    let (x, y) = curve.point(p);
    let (du, dv) = curve.tangent(p);
    let (ddu, ddv) = curve.second(p);
    let speed2 = du * du + dv * dv;
    let curvature = if speed2 > 0.0 { (du * ddv - dv * ddu) / (speed2 * speed2.sqrt()) } else { 0.0 };
    CurvePose { x, y, hdg: dv.atan2(du), curvature }
}

impl ParamPoly3 {
    /// Prepare a paramPoly3 of declared `length`.
    pub fn new(u: [f64; 4], v: [f64; 4], p_range: PRange, length: f64) -> ParamPoly3 {
        let length = length.max(0.0);
        let p_max = match p_range {
            PRange::ArcLength => length,
            PRange::Normalized => 1.0,
        };
        let table = ArcLengthTable::new(CubicCurve { u, v }, p_max, length);
        ParamPoly3 { u, v, p_range, length, table }
    }

    /// True arc length of the curve (compare with the declared `length`).
    pub fn arc_length(&self) -> f64 {
        self.table.total()
    }

    /// Local pose at arc length `ds` (see the module doc for the scaling).
    pub fn local(&self, ds: f64) -> CurvePose {
        let scale = if self.length > 0.0 { self.table.total() / self.length } else { 0.0 };
        pose_of(&self.table.curve, self.table.param_at(ds * scale))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_line_in_both_ranges() {
        // u = 3p (normalized, length 3) and u = p (arcLength, length 3): same segment
        let n = ParamPoly3::new([0.0, 3.0, 0.0, 0.0], [0.0; 4], PRange::Normalized, 3.0);
        let a = ParamPoly3::new([0.0, 1.0, 0.0, 0.0], [0.0; 4], PRange::ArcLength, 3.0);
        for i in 0..=6 {
            let s = f64::from(i) * 0.5;
            let (pn, pa) = (n.local(s), a.local(s));
            assert!((pn.x - s).abs() < 1e-12 && (pa.x - s).abs() < 1e-12);
            assert!(pn.y.abs() < 1e-15 && pa.y.abs() < 1e-15);
        }
    }

    #[test]
    fn normalized_and_arc_length_describe_the_same_curve() {
        // Curve C(q) = (q, 0.01 q²) for q in [0, 10]; with p = q/10 for normalized.
        let len = {
            // arc length of y = 0.01x² from 0..10: ∫ sqrt(1 + (0.02x)²) dx, closed form
            let k = 0.02;
            let x: f64 = 10.0;
            (x * (1.0 + (k * x).powi(2)).sqrt() + (k * x).asinh() / k) / 2.0
        };
        let a = ParamPoly3::new([0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.01, 0.0], PRange::ArcLength, 10.0);
        let n = ParamPoly3::new([0.0, 10.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], PRange::Normalized, len);
        assert!((n.arc_length() - len).abs() < 1e-10);
        // arcLength range with p_max = 10 covers the same curve, whose true length is `len`
        assert!((a.arc_length() - len).abs() < 1e-10);
        let end = n.local(len);
        assert!((end.x - 10.0).abs() < 1e-9 && (end.y - 1.0).abs() < 1e-9);
        let mid_n = n.local(len / 2.0);
        // declared length 10 ≠ true length: s is scaled, so s = 5 is half way by arc length
        let mid_a = a.local(5.0);
        assert!((mid_a.x - mid_n.x).abs() < 1e-9 && (mid_a.y - mid_n.y).abs() < 1e-9);
        // hand check of the midpoint by arc length: point on y = 0.01 x² at arc length len/2
        let (x, y) = (mid_n.x, mid_n.y);
        assert!((y - 0.01 * x * x).abs() < 1e-12);
        let k = 0.02;
        let s_of_x = (x * (1.0 + (k * x).powi(2)).sqrt() + (k * x).asinh() / k) / 2.0;
        assert!((s_of_x - len / 2.0).abs() < 1e-9);
    }

    #[test]
    fn hand_computed_cubic_point() {
        // u = p, v = p³/100 on arcLength; at p = 2: (2, 0.08), heading atan(0.12)
        let c = ParamPoly3::new([0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.01], PRange::ArcLength, 2.0);
        let pose = pose_of(&CubicCurve { u: c.u, v: c.v }, 2.0);
        assert!((pose.x - 2.0).abs() < 1e-15 && (pose.y - 0.08).abs() < 1e-15);
        assert!((pose.hdg - 0.12f64.atan()).abs() < 1e-15);
    }
}

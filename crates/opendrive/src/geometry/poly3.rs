//! `<poly3>` (deprecated but read): v = a + b·u + c·u² + d·u³ in the local frame, s = arc length.

use super::arc_length_table::{ArcLengthTable, CubicCurve};
use super::param_poly3::pose_of;
use super::pose::CurvePose;

/// A cubic v(u) with u along the start heading.
#[derive(Debug, Clone, PartialEq)]
pub struct Poly3 {
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub d: f64,
    table: ArcLengthTable,
}

impl Poly3 {
    /// Prepare a poly3 geometry of arc length `length`.
    pub fn new(a: f64, b: f64, c: f64, d: f64, length: f64) -> Poly3 {
        // u never exceeds the arc length, so tabulating u ∈ [0, length] covers the geometry.
        let curve = CubicCurve { u: [0.0, 1.0, 0.0, 0.0], v: [a, b, c, d] };
        Poly3 { a, b, c, d, table: ArcLengthTable::new(curve, length.max(0.0), length) }
    }

    /// Local pose at arc length `ds`.
    pub fn local(&self, ds: f64) -> CurvePose {
        pose_of(&self.table.curve, self.table.param_at(ds))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_poly3_with_offset() {
        // v = 2 + 0.5 u: a straight line at angle atan(0.5) starting at (0, 2)
        let p = Poly3::new(2.0, 0.5, 0.0, 0.0, 100.0);
        let q = p.local(10.0);
        let ang = 0.5f64.atan();
        assert!((q.x - 10.0 * ang.cos()).abs() < 1e-9);
        assert!((q.y - (2.0 + 10.0 * ang.sin())).abs() < 1e-9);
        assert!((q.hdg - ang).abs() < 1e-12);
    }

    #[test]
    fn parabola_arc_length_hand_computed() {
        // v = u²: arc length to u=1 is (2√5 + asinh 2)/4 = 1.478942857544597
        let len = (2.0 * 5f64.sqrt() + 2f64.asinh()) / 4.0;
        let p = Poly3::new(0.0, 0.0, 1.0, 0.0, len);
        let end = p.local(len);
        assert!((end.x - 1.0).abs() < 1e-9 && (end.y - 1.0).abs() < 1e-9, "{end:?}");
        assert!((end.hdg - 2f64.atan()).abs() < 1e-9);
        // curvature of y = x² at x=1: 2 / (1+4)^1.5
        assert!((end.curvature - 2.0 / 5f64.powf(1.5)).abs() < 1e-9);
    }
}

//! `<line>`: straight segment in the geometry's local frame.

use super::pose::CurvePose;

/// Local pose `ds` along a line starting at the origin heading +x.
pub fn line_local(ds: f64) -> CurvePose {
    CurvePose { x: ds, y: 0.0, hdg: 0.0, curvature: 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moves_along_x() {
        let p = line_local(12.5);
        assert_eq!((p.x, p.y, p.hdg, p.curvature), (12.5, 0.0, 0.0, 0.0));
    }
}

//! `<arc>`: constant curvature in the geometry's local frame.

use super::pose::CurvePose;

/// Local pose `ds` along an arc of curvature `k` starting at the origin heading +x.
pub fn arc_local(k: f64, ds: f64) -> CurvePose {
    let phi = k * ds;
    // Below this angle the closed form loses digits to cancellation; the series is exact
    // to far below 1e-15 m there.
    let (x, y) = if phi.abs() < 1e-6 {
        let phi2 = phi * phi;
        (ds * (1.0 - phi2 / 6.0), ds * phi * (0.5 - phi2 / 24.0))
    } else {
        // 1 - cos φ = 2 sin²(φ/2) avoids cancellation for small φ.
        let half = (0.5 * phi).sin();
        (phi.sin() / k, 2.0 * half * half / k)
    };
    CurvePose { x, y, hdg: phi, curvature: k }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_circle_left_and_right() {
        let r = 50.0;
        let quarter = std::f64::consts::FRAC_PI_2 * r;
        let p = arc_local(1.0 / r, quarter);
        assert!((p.x - r).abs() < 1e-12 && (p.y - r).abs() < 1e-12);
        assert!((p.hdg - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        let q = arc_local(-1.0 / r, quarter);
        assert!((q.x - r).abs() < 1e-12 && (q.y + r).abs() < 1e-12);
    }

    #[test]
    fn every_point_lies_on_the_circle() {
        // centre of a left-turning arc from the origin heading +x is (0, R)
        for &k in &[0.2, 1e-3, 1e-7, -0.05] {
            let r = 1.0 / k;
            for i in 0..50 {
                let ds = f64::from(i) * 3.7;
                let p = arc_local(k, ds);
                let dist = (p.x * p.x + (p.y - r) * (p.y - r)).sqrt();
                assert!((dist - r.abs()).abs() < 1e-9 * r.abs().max(1.0), "k={k} ds={ds}");
                // chord length 2R sin(φ/2)
                let chord = (p.x * p.x + p.y * p.y).sqrt();
                let want = (2.0 * r * (0.5 * k * ds).sin()).abs();
                assert!((chord - want).abs() < 1e-9, "chord k={k} ds={ds}");
            }
        }
    }
}

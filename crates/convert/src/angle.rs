//! Headings: CommonRoad wants orientations in (−π, π], and interpolating between two headings
//! must go the short way round (from 179° to −179° is 2°, not 358°).

use std::f64::consts::{PI, TAU};

/// `a` wrapped to (−π, π]. Non-finite input is returned unchanged (validation reports it).
pub fn wrap_angle(a: f64) -> f64 {
    if !a.is_finite() {
        return a;
    }
    let r = a.rem_euclid(TAU); // [0, 2π)
    if r > PI {
        r - TAU
    } else {
        r
    }
}

/// The heading a fraction `f` (0..=1) of the way from `a` to `b` along the shorter arc,
/// wrapped to (−π, π].
pub fn lerp_angle(a: f64, b: f64, f: f64) -> f64 {
    let d = wrap_angle(b - a);
    wrap_angle(a + f * d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wraps_into_half_open_interval() {
        assert!((wrap_angle(3.0 * PI) - PI).abs() < 1e-12);
        assert!((wrap_angle(-PI) - PI).abs() < 1e-12, "−π maps to +π");
        assert!((wrap_angle(PI) - PI).abs() < 1e-12);
        assert!((wrap_angle(-3.0 * PI / 2.0) - PI / 2.0).abs() < 1e-12);
        assert!((wrap_angle(7.0) - (7.0 - TAU)).abs() < 1e-12);
        assert_eq!(wrap_angle(0.0), 0.0);
        assert!(wrap_angle(f64::NAN).is_nan());
    }

    #[test]
    fn interpolates_along_the_shorter_arc() {
        let a = 179f64.to_radians();
        let b = (-179f64).to_radians();
        // halfway is ±180°, not 0°
        let mid = lerp_angle(a, b, 0.5);
        assert!((mid.abs() - PI).abs() < 1e-9, "{mid}");
        // a quarter of the way: 179.5°
        let q = lerp_angle(a, b, 0.25);
        assert!((q - 179.5f64.to_radians()).abs() < 1e-9, "{q}");
        // the other way round
        let q = lerp_angle(b, a, 0.25);
        assert!((q - (-179.5f64).to_radians()).abs() < 1e-9, "{q}");
        // ordinary case
        assert!((lerp_angle(0.0, 1.0, 0.3) - 0.3).abs() < 1e-12);
    }
}

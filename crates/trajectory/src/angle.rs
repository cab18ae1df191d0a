//! Heading arithmetic.

use std::f64::consts::{PI, TAU};

/// Heading in [0, 2π) (esmini's convention for trajectory headings).
pub(crate) fn normalize(h: f64) -> f64 {
    let r = h.rem_euclid(TAU);
    if r >= TAU {
        0.0
    } else {
        r
    }
}

/// Signed smallest difference `a - b`, in (-π, π].
pub(crate) fn diff(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    if d > PI {
        d - TAU
    } else {
        d
    }
}

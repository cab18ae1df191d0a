//! Heading arithmetic.

use std::f64::consts::{PI, TAU};

/// Heading in [0, 2π) (esmini's convention for trajectory headings).
pub(crate) fn normalize(h: f64) -> f64 {
    let r = in_turn(h);
    if r >= TAU {
        0.0
    } else {
        r
    }
}

/// Signed smallest difference `a - b`, in (-π, π].
pub(crate) fn diff(a: f64, b: f64) -> f64 {
    let d = in_turn(a - b);
    if d > PI {
        d - TAU
    } else {
        d
    }
}

/// `x.rem_euclid(TAU)`, skipping the remainder (a software `fmod`) when x is already in
/// [0, 2π), where the remainder is x exactly.
fn in_turn(x: f64) -> f64 {
    if (0.0..TAU).contains(&x) {
        x
    } else {
        x.rem_euclid(TAU)
    }
}

//! Angles wrapped: to [−π, π) (`wrap`), to [0, 2π) as esmini reports headings (`wrap_2pi`),
//! and esmini's GetAngleInIntervalMinusPIPlusPI and GetAngleDifference, whose remainder-based
//! wrap keeps the sign of ±π (π stays π where `wrap` gives −π: a tie esmini's steering reads).

/// Angle wrapped to [−π, π).
pub(crate) fn wrap(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let mut x = (a + std::f64::consts::PI) % two_pi;
    if x < 0.0 {
        x += two_pi;
    }
    x - std::f64::consts::PI
}

/// Angle in [0, 2π) as esmini reports headings.
pub(crate) fn wrap_2pi(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let x = a % two_pi;
    if x < 0.0 {
        x + two_pi
    } else {
        x
    }
}

/// esmini's GetAngleInIntervalMinusPIPlusPI.
pub(crate) fn angle_pi(a: f64) -> f64 {
    let mut b = a % (2.0 * std::f64::consts::PI);
    if b < -std::f64::consts::PI {
        b += 2.0 * std::f64::consts::PI;
    } else if b > std::f64::consts::PI {
        b -= 2.0 * std::f64::consts::PI;
    }
    b
}

/// esmini's GetAngleDifference: a − b by [`angle_pi`].
pub(crate) fn angle_difference(a: f64, b: f64) -> f64 {
    angle_pi(a - b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn the_two_wraps_part_at_plus_pi() {
        assert_eq!(wrap(PI), -PI);
        assert_eq!(angle_pi(PI), PI);
        assert_eq!(angle_pi(-PI), -PI);
        assert_eq!(wrap_2pi(-0.5 * PI), 1.5 * PI);
        assert!((angle_difference(0.1, 2.0 * PI - 0.1) - 0.2).abs() < 1e-12);
    }
}

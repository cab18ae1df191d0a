//! Angles wrapped: to [−π, π) (`wrap`), to [0, 2π) as esmini reports headings (`wrap_2pi`),
//! and esmini's GetAngleInIntervalMinusPIPlusPI and GetAngleDifference, whose remainder-based
//! wrap keeps the sign of ±π (π stays π where `wrap` gives −π: a tie esmini's steering reads).
//! An angle already in range skips the remainder (a software `fmod`, once 1.7 % of a run): the
//! remainder of a value inside its interval is that value exactly, so the bits are the same.

/// Angle wrapped to [−π, π).
pub(crate) fn wrap(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let shifted = a + std::f64::consts::PI;
    if (0.0..two_pi).contains(&shifted) {
        return shifted - std::f64::consts::PI;
    }
    let mut x = shifted % two_pi;
    if x < 0.0 {
        x += two_pi;
    }
    x - std::f64::consts::PI
}

/// Angle in [0, 2π) as esmini reports headings.
pub(crate) fn wrap_2pi(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    if (0.0..two_pi).contains(&a) {
        return a;
    }
    let x = a % two_pi;
    if x < 0.0 {
        x + two_pi
    } else {
        x
    }
}

/// esmini's GetAngleInIntervalMinusPIPlusPI.
pub(crate) fn angle_pi(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let mut b = if a.abs() < two_pi { a } else { a % two_pi };
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

    /// The in-range shortcut gives the remainder's bits exactly, in range and out of it.
    #[test]
    fn the_shortcut_keeps_the_remainders_bits() {
        let slow_wrap = |a: f64| {
            let mut x = (a + PI) % (2.0 * PI);
            if x < 0.0 {
                x += 2.0 * PI;
            }
            x - PI
        };
        let slow_2pi = |a: f64| {
            let x = a % (2.0 * PI);
            if x < 0.0 {
                x + 2.0 * PI
            } else {
                x
            }
        };
        let slow_pi = |a: f64| {
            let mut b = a % (2.0 * PI);
            if b < -PI {
                b += 2.0 * PI;
            } else if b > PI {
                b -= 2.0 * PI;
            }
            b
        };
        let mut a = -20.0;
        while a < 20.0 {
            for x in [a, -PI, PI, 2.0 * PI, -2.0 * PI, 0.0, -0.0, f64::from_bits(a.to_bits() + 1)] {
                assert_eq!(wrap(x).to_bits(), slow_wrap(x).to_bits(), "wrap {x}");
                assert_eq!(wrap_2pi(x).to_bits(), slow_2pi(x).to_bits(), "wrap_2pi {x}");
                assert_eq!(angle_pi(x).to_bits(), slow_pi(x).to_bits(), "angle_pi {x}");
            }
            a += 0.0137;
        }
    }
}

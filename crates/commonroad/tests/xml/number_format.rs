//! `xs:decimal` formatting: fixed notation, bounded rounding error, no exponent, no NaN/inf.

use commonroad::xml::{format_decimal, is_written_positive, DECIMALS};
use proptest::prelude::*;

fn f(v: f64) -> String {
    format_decimal(v).unwrap()
}

/// `-?digits.digits` — the lexical space we promise (a subset of xs:decimal).
fn is_fixed_decimal(s: &str) -> bool {
    let body = s.strip_prefix('-').unwrap_or(s);
    let Some((int, frac)) = body.split_once('.') else {
        return false;
    };
    !int.is_empty() && !frac.is_empty() && frac.len() <= DECIMALS && int.bytes().all(|b| b.is_ascii_digit()) && frac.bytes().all(|b| b.is_ascii_digit())
}

#[test]
fn simple_values_keep_one_decimal_and_trim_zeros() {
    assert_eq!(f(0.0), "0.0");
    assert_eq!(f(20.0), "20.0");
    assert_eq!(f(1.5), "1.5");
    assert_eq!(f(-2.25), "-2.25");
    assert_eq!(f(3.5), "3.5");
    assert_eq!(f(0.1), "0.1");
}

#[test]
fn negative_zero_and_tiny_negatives_are_plain_zero() {
    assert_eq!(f(-0.0), "0.0");
    assert_eq!(f(-1e-7), "0.0");
    assert_eq!(f(-4e-7), "0.0");
}

#[test]
fn tiny_values_round_at_the_sixth_decimal_without_exponent() {
    assert_eq!(f(1e-7), "0.0");
    assert_eq!(f(1e-300), "0.0");
    assert_eq!(f(f64::MIN_POSITIVE), "0.0");
    assert_eq!(f(6e-7), "0.000001");
    assert_eq!(f(-6e-7), "-0.000001");
    assert_eq!(f(1e-6), "0.000001");
    assert_eq!(f(1.2e-5), "0.000012");
}

#[test]
fn rounding_is_to_nearest_at_six_decimals() {
    assert_eq!(f(1.23456789), "1.234568");
    assert_eq!(f(-1.23456749), "-1.234567");
    assert_eq!(f(0.9999996), "1.0");
    assert_eq!(f(-0.9999996), "-1.0");
    assert_eq!(f(2.0000004), "2.0");
    // pi to 6 decimals: 3.141592|65… → 3.141593
    assert_eq!(f(std::f64::consts::PI), "3.141593");
}

#[test]
fn large_values_are_written_in_full() {
    assert_eq!(f(1e21), "1000000000000000000000.0");
    assert_eq!(f(-123456789012.5), "-123456789012.5");
    // the exact integer value of f64::MAX (computed independently with Python's int())
    let max = "179769313486231570814527423731704356798070567525844996598917476803157260780028538760589558632766878171540458953514382464234321326889464182768467546703537516986049910576551282076245490090389328944075868508455133942304583236903222948165808559332123348274797826204144723168738177180919299881250404026184124858368";
    assert_eq!(f(f64::MAX), format!("{max}.0"));
    assert_eq!(f(f64::MIN), format!("-{max}.0"));
}

#[test]
fn non_finite_numbers_cannot_be_written() {
    assert_eq!(format_decimal(f64::NAN), None);
    assert_eq!(format_decimal(f64::INFINITY), None);
    assert_eq!(format_decimal(f64::NEG_INFINITY), None);
}

#[test]
fn positive_decimals_must_survive_rounding() {
    assert!(is_written_positive(1.0));
    assert!(is_written_positive(1e-6));
    assert!(!is_written_positive(1e-9));
    assert!(!is_written_positive(0.0));
    assert!(!is_written_positive(-1.0));
    assert!(!is_written_positive(f64::NAN));
}

proptest! {
    /// For coordinates up to 1e7 m the written value is within 0.5e-6 (+ f64 rounding) of the
    /// value — far inside the 0.1 mm budget for lane bounds.
    #[test]
    fn written_value_is_within_half_a_micrometre(v in -1e7f64..1e7f64) {
        let s = f(v);
        prop_assert!(is_fixed_decimal(&s), "{s}");
        let back: f64 = s.parse().unwrap();
        prop_assert!((back - v).abs() <= 0.5e-6 + 4.0 * f64::EPSILON * v.abs(), "{v} -> {s}");
    }

    #[test]
    fn any_finite_value_is_fixed_notation(v in proptest::num::f64::NORMAL | proptest::num::f64::SUBNORMAL | proptest::num::f64::ZERO) {
        let s = f(v);
        prop_assert!(is_fixed_decimal(&s), "{v:e} -> {s}");
    }
}

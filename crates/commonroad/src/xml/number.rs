//! Numbers as `xs:decimal`: fixed notation, never an exponent, never NaN or infinity.
//!
//! Precision: [`DECIMALS`] = 6 digits after the point, i.e. a rounding error of at most
//! 0.5 µm for lengths. Lane bounds must stay within 0.1 mm of the computed geometry (which is
//! itself held to 1 mm of the exact OpenDRIVE border), so 6 decimals leave a factor 200 of
//! headroom, whereas commonroad-io's own 4 decimals (0.05 mm) would eat half the budget. f64
//! still resolves 1e-6 at coordinates up to ~1e9 m, so the digits are real even for projected
//! (UTM-sized) coordinates. Angles get 1e-6 rad, speeds 1e-6 m/s. Trailing zeros are trimmed
//! (one digit after the point is kept) to keep files small; `-0` is written as `0.0`.

use std::fmt::Write;

/// Digits after the decimal point.
pub const DECIMALS: usize = 6;

/// `v` in fixed notation with at most [`DECIMALS`] decimals (rounded to nearest, ties of the
/// exact binary value to even), trailing zeros trimmed, e.g. `1.5`, `-0.000001`, `20.0`.
/// Returns `None` for NaN and infinities, which `xs:decimal` cannot express.
pub fn format_decimal(v: f64) -> Option<String> {
    let mut s = String::new();
    push_decimal(&mut s, v).then_some(s)
}

/// Appends [`format_decimal`]`(v)` to `out` without allocating (the writer formats tens of
/// thousands of numbers per file). Returns false, leaving `out` unchanged, for NaN and
/// infinities.
pub(crate) fn push_decimal(out: &mut String, v: f64) -> bool {
    if !v.is_finite() {
        return false;
    }
    let start = out.len();
    // Writing into a String cannot fail.
    let _ = write!(out, "{:.*}", DECIMALS, v);
    // keep at least one digit after the point
    while out.ends_with('0') && !out.ends_with(".0") {
        out.pop();
    }
    if out.get(start..) == Some("-0.0") {
        out.truncate(start);
        out.push_str("0.0");
    }
    true
}

/// Whether `v` is written as a positive decimal (`positiveDecimal`): finite, > 0, and not
/// rounded to zero at [`DECIMALS`] decimals.
pub fn is_written_positive(v: f64) -> bool {
    v > 0.0 && format_decimal(v).is_some_and(|s| s.bytes().any(|b| matches!(b, b'1'..=b'9')))
}

//! Comparison rules of conditions, with esmini's tolerance (EvaluateRule(double) in
//! OSCCondition.cpp: strict comparisons need a margin of SMALL_NUMBER, 1e-6, equality accepts
//! it).

use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL;
use openscenario::Rule;

pub(crate) fn compare(a: f64, b: f64, rule: Rule) -> bool {
    match rule {
        Rule::GreaterThan => a > b + SMALL,
        Rule::GreaterOrEqual => a >= b - SMALL,
        Rule::LessThan => a < b - SMALL,
        Rule::LessOrEqual => a <= b + SMALL,
        Rule::EqualTo => (a - b).abs() < SMALL || a == b,
        Rule::NotEqualTo => !((a - b).abs() < SMALL || a == b),
    }
}

/// Compare two values given as text: numerically when both parse, else as strings.
pub(crate) fn compare_text(a: &str, b: &str, rule: Rule) -> bool {
    let num = |s: &str| -> Option<f64> {
        match s.trim() {
            "true" => Some(1.0),
            "false" => Some(0.0),
            t => t.parse::<f64>().ok(),
        }
    };
    if let (Some(x), Some(y)) = (num(a), num(b)) {
        return compare(x, y, rule);
    }
    compare_exact(a, b, rule)
}

/// A rule without tolerance: esmini's EvaluateRule for ints, strings (byte order, as
/// std::string compares) and bools (true above false).
pub(crate) fn compare_exact<T: PartialOrd + ?Sized>(a: &T, b: &T, rule: Rule) -> bool {
    match rule {
        Rule::GreaterThan => a > b,
        Rule::GreaterOrEqual => a >= b,
        Rule::LessThan => a < b,
        Rule::LessOrEqual => a <= b,
        Rule::EqualTo => a == b,
        Rule::NotEqualTo => a != b,
    }
}

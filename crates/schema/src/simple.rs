//! Is an attribute's literal text a value of its simple type?

use crate::model::{Primitive, SimpleKind};

/// What an attribute value is, once checked against its type.
#[derive(Debug, Clone, PartialEq)]
pub enum LiteralCheck {
    /// A plain value of the type.
    Valid,
    /// A value of an enumeration that the schema marks deprecated.
    DeprecatedLiteral,
    /// `$name`: to be resolved against the parameter declarations in scope, then checked.
    Parameter,
    /// `${...}`: to be evaluated, then checked.
    Expression,
    /// Not a value of the type; the text says why, in a reader's words.
    Invalid(String),
}

/// Checks `value` against `kind`. Parameter references and expressions are recognised (when the
/// type allows them) but not resolved: that needs the scope, which the caller has.
pub fn check_literal(kind: &SimpleKind, value: &str) -> LiteralCheck {
    if value.starts_with("${") && kind.allows_expression {
        return LiteralCheck::Expression;
    }
    if value.starts_with('$') && kind.allows_parameter {
        return LiteralCheck::Parameter;
    }
    if let Some(literals) = &kind.literals {
        return match literals.iter().find(|l| l.value == value) {
            Some(l) if l.deprecated => LiteralCheck::DeprecatedLiteral,
            Some(_) => LiteralCheck::Valid,
            None => {
                let allowed: Vec<&str> = literals.iter().filter(|l| !l.deprecated).map(|l| l.value.as_str()).collect();
                LiteralCheck::Invalid(format!("'{}' is not one of: {}", value, allowed.join(", ")))
            }
        };
    }
    match check_primitive(kind.primitive, value) {
        Ok(()) => LiteralCheck::Valid,
        Err(why) => LiteralCheck::Invalid(why),
    }
}

/// Checks a value (after any parameter substitution) against an XSD built-in type.
pub fn check_primitive(primitive: Primitive, value: &str) -> Result<(), String> {
    // XSD collapses whitespace around every non-string value.
    let v = value.trim();
    let ok = match primitive {
        Primitive::String => true,
        Primitive::Boolean => matches!(v, "true" | "false" | "1" | "0"),
        Primitive::Double => is_xsd_double(v),
        Primitive::Int => v.parse::<i32>().is_ok(),
        Primitive::UnsignedInt => v.trim_start_matches('+').parse::<u32>().is_ok() && !v.starts_with("+-"),
        Primitive::UnsignedShort => v.trim_start_matches('+').parse::<u16>().is_ok() && !v.starts_with("+-"),
        Primitive::DateTime => is_xsd_date_time(v),
    };
    if ok {
        return Ok(());
    }
    let range = match primitive {
        Primitive::Int => " (an integer in [-2147483648, 2147483647])",
        Primitive::UnsignedInt => " (an integer in [0, 4294967295])",
        Primitive::UnsignedShort => " (an integer in [0, 65535])",
        Primitive::Boolean => " (true, false, 1 or 0)",
        Primitive::DateTime => " (YYYY-MM-DDThh:mm:ss with an optional fraction and zone)",
        _ => "",
    };
    Err(format!("'{value}' is not a valid {}{range}", primitive.xsd_name()))
}

fn is_xsd_double(v: &str) -> bool {
    if matches!(v, "INF" | "+INF" | "-INF" | "NaN") {
        return true;
    }
    // Rust accepts "inf", "infinity" and "nan" in any case; XSD does not.
    let has_letters = v.chars().any(|c| c.is_ascii_alphabetic() && c != 'e' && c != 'E');
    !v.is_empty() && !has_letters && v.parse::<f64>().is_ok()
}

fn is_xsd_date_time(v: &str) -> bool {
    // [-]YYYY-MM-DDThh:mm:ss[.s+][Z|(+|-)hh:mm]
    let b = v.strip_prefix('-').unwrap_or(v).as_bytes();
    let digits = |s: &[u8]| !s.is_empty() && s.iter().all(u8::is_ascii_digit);
    if b.len() < 19 || b.get(4) != Some(&b'-') || b.get(7) != Some(&b'-') || b.get(10) != Some(&b'T') {
        return false;
    }
    if b.get(13) != Some(&b':') || b.get(16) != Some(&b':') {
        return false;
    }
    let fields = [&b[0..4], &b[5..7], &b[8..10], &b[11..13], &b[14..16], &b[17..19]];
    if !fields.iter().all(|f| digits(f)) {
        return false;
    }
    let num = |f: &[u8]| f.iter().fold(0u32, |acc, d| acc * 10 + u32::from(d - b'0'));
    let (month, day, hour, minute, second) = (num(fields[1]), num(fields[2]), num(fields[3]), num(fields[4]), num(fields[5]));
    if !(1..=12).contains(&month) || !(1..=31).contains(&day) || hour > 24 || minute > 59 || second > 59 {
        return false;
    }
    let mut rest = &b[19..];
    if let Some(frac) = rest.strip_prefix(b".") {
        let n = frac.iter().take_while(|c| c.is_ascii_digit()).count();
        if n == 0 {
            return false;
        }
        rest = &frac[n..];
    }
    match rest {
        [] | [b'Z'] => true,
        [sign, h1, h2, b':', m1, m2] if (*sign == b'+' || *sign == b'-') => digits(&[*h1, *h2, *m1, *m2]),
        _ => false,
    }
}

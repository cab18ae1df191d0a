//! Typed parameter values for the checks that compare them: declared types, ValueConstraints.

use schema::Primitive;

/// The primitive a `parameterType` / `variableType` literal names (`int` is accepted for
/// `integer`, as esmini and the ASAM API do).
pub(super) fn primitive_of_parameter_type(text: &str) -> Option<Primitive> {
    Some(match text {
        "integer" | "int" => Primitive::Int,
        "double" => Primitive::Double,
        "unsignedInt" => Primitive::UnsignedInt,
        "unsignedShort" => Primitive::UnsignedShort,
        "boolean" => Primitive::Boolean,
        "string" => Primitive::String,
        "dateTime" => Primitive::DateTime,
        _ => return None,
    })
}

/// Checks a parameter or variable value against its declared type. Integer types also take an
/// integral decimal (`-5.0`), as esmini and the ASAM API read them.
pub(super) fn fits_declared_type(p: Primitive, value: &str) -> Result<(), String> {
    let strict = schema::simple::check_primitive(p, value);
    if strict.is_ok() || !matches!(p, Primitive::Int | Primitive::UnsignedInt | Primitive::UnsignedShort) {
        return strict;
    }
    let (lo, hi) = match p {
        Primitive::Int => (f64::from(i32::MIN), f64::from(i32::MAX)),
        Primitive::UnsignedInt => (0.0, f64::from(u32::MAX)),
        _ => (0.0, f64::from(u16::MAX)),
    };
    match value.trim().parse::<f64>() {
        Ok(v) if v.fract() == 0.0 && (lo..=hi).contains(&v) => Ok(()),
        _ => strict,
    }
}

/// The declared type as the schema's ParameterType literal says it.
pub(super) fn parameter_type_name(p: Primitive) -> &'static str {
    match p {
        Primitive::Int => "integer",
        other => other.xsd_name(),
    }
}

/// A value ordered the way its type orders: numbers numerically, booleans false < true,
/// date-times as instants (zones applied), strings by their bytes.
#[derive(Debug, Clone, PartialEq, PartialOrd)]
pub(super) enum Ordered {
    Number(f64),
    Text(String),
}

pub(super) fn ordered(p: Primitive, text: &str) -> Option<Ordered> {
    let t = text.trim();
    match p {
        Primitive::String => Some(Ordered::Text(text.to_string())),
        Primitive::Boolean => match t {
            "true" | "1" => Some(Ordered::Number(1.0)),
            "false" | "0" => Some(Ordered::Number(0.0)),
            _ => None,
        },
        Primitive::DateTime => date_time_seconds(t).map(Ordered::Number),
        _ => {
            fits_declared_type(p, t).ok()?;
            t.parse::<f64>().ok().map(Ordered::Number)
        }
    }
}

/// `rule` applied as `value rule bound`; `None` for a rule name the schema does not have.
pub(super) fn holds(rule: &str, value: &Ordered, bound: &Ordered) -> Option<bool> {
    use std::cmp::Ordering::*;
    let ord = value.partial_cmp(bound)?;
    Some(match rule {
        "equalTo" => ord == Equal,
        "notEqualTo" => ord != Equal,
        "greaterThan" => ord == Greater,
        "lessThan" => ord == Less,
        "greaterOrEqual" => ord != Less,
        "lessOrEqual" => ord != Greater,
        _ => return None,
    })
}

/// Seconds since 1970-01-01T00:00:00Z of an xsd:dateTime (no zone: read as UTC).
fn date_time_seconds(t: &str) -> Option<f64> {
    schema::simple::check_primitive(Primitive::DateTime, t).ok()?;
    let (neg, body) = match t.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, t),
    };
    let num = |s: &str| s.parse::<i64>().ok();
    let mut year = num(body.get(0..4)?)?;
    if neg {
        year = -year;
    }
    let month = num(body.get(5..7)?)?;
    let day = num(body.get(8..10)?)?;
    let hour = num(body.get(11..13)?)?;
    let minute = num(body.get(14..16)?)?;
    let mut rest = body.get(19..)?;
    let mut seconds = num(body.get(17..19)?)? as f64;
    if let Some(frac) = rest.strip_prefix('.') {
        let n = frac.bytes().take_while(u8::is_ascii_digit).count();
        seconds += format!("0.{}", frac.get(..n)?).parse::<f64>().ok()?;
        rest = frac.get(n..)?;
    }
    let offset_minutes = match rest {
        "" | "Z" => 0,
        zone => {
            let sign = if zone.starts_with('-') { -1 } else { 1 };
            sign * (num(zone.get(1..3)?)? * 60 + num(zone.get(4..6)?)?)
        }
    };
    let days = days_from_civil(year, month, day);
    Some((days * 86_400 + hour * 3600 + (minute - offset_minutes) * 60) as f64 + seconds)
}

/// Days since 1970-01-01 of a proleptic Gregorian date (Howard Hinnant's algorithm).
fn days_from_civil(y: i64, m: i64, d: i64) -> i64 {
    let y = if m <= 2 { y - 1 } else { y };
    let era = y.div_euclid(400);
    let yoe = y - era * 400;
    let mp = (m + 9) % 12;
    let doy = (153 * mp + 2) / 5 + d - 1;
    let doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    era * 146_097 + doe - 719_468
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn date_times_compare_as_instants() {
        let a = ordered(Primitive::DateTime, "2021-07-09T11:00:00.34+04:00").expect("a");
        let b = ordered(Primitive::DateTime, "2021-07-09T10:00:00.34+03:00").expect("b");
        assert_eq!(holds("equalTo", &a, &b), Some(true));
        let c = ordered(Primitive::DateTime, "2021-07-09T11:00:00.34+03:00").expect("c");
        assert_eq!(holds("greaterThan", &c, &b), Some(true));
        assert_eq!(date_time_seconds("1970-01-02T00:00:00Z"), Some(86_400.0));
    }

    #[test]
    fn booleans_and_strings_order() {
        let t = ordered(Primitive::Boolean, "true").expect("t");
        let f = ordered(Primitive::Boolean, "false").expect("f");
        assert_eq!(holds("greaterThan", &t, &f), Some(true));
        let upper = ordered(Primitive::String, "Abcd").expect("A");
        let lower = ordered(Primitive::String, "abcd").expect("a");
        assert_eq!(holds("lessThan", &upper, &lower), Some(true));
        assert_eq!(holds("equalTo", &upper, &lower), Some(false));
    }
}

//! How esmini reads a number written as text that is not one. Its reader converts attribute
//! values with C's `atof` and `atoi` (`strtod`/`strtoi` in CommonMini.cpp): the leading number
//! of the text, or 0 when it starts with none — so a parameter whose value is `None` is 0. The
//! standard forbids such values; osc2cr reports them as problems and, with `--lenient`, reads
//! them as esmini does, through these two functions.

/// C's `atof` for the values a scenario may hold: leading white space, a sign, decimal digits
/// with a point and an exponent, or `inf`/`infinity`/`nan` in any case; 0 when no number starts
/// the text. Hexadecimal floats are read as C reads them too (`0x1A` is 26).
pub(crate) fn atof(text: &str) -> f64 {
    let (negative, rest) = sign(text);
    let magnitude = special(rest).or_else(|| hexadecimal(rest)).unwrap_or_else(|| decimal(rest));
    if negative {
        -magnitude
    } else {
        magnitude
    }
}

/// C's `atoi`: leading white space, a sign and decimal digits; 0 when none start the text
/// (a value beyond the range of `i64` saturates).
pub(crate) fn atoi(text: &str) -> i64 {
    let (negative, rest) = sign(text);
    let mut v: i64 = 0;
    for d in rest.bytes().take_while(u8::is_ascii_digit) {
        v = v.saturating_mul(10).saturating_add(i64::from(d - b'0'));
    }
    if negative {
        -v
    } else {
        v
    }
}

/// Leading white space skipped, the sign read: whether it is negative, and what follows it.
fn sign(text: &str) -> (bool, &str) {
    let t = text.trim_start_matches(|c: char| c.is_ascii_whitespace());
    match t.as_bytes().first() {
        Some(b'-') => (true, &t[1..]),
        Some(b'+') => (false, &t[1..]),
        _ => (false, t),
    }
}

fn special(t: &str) -> Option<f64> {
    let lower: String = t.chars().take(8).collect::<String>().to_ascii_lowercase();
    if lower.starts_with("inf") {
        Some(f64::INFINITY)
    } else if lower.starts_with("nan") {
        Some(f64::NAN)
    } else {
        None
    }
}

/// `0x` followed by hexadecimal digits, an optional point and fraction and an optional binary
/// exponent `p±n`; None when no hexadecimal digit follows the prefix.
fn hexadecimal(t: &str) -> Option<f64> {
    let body = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X"))?;
    let mut chars = body.chars().peekable();
    let mut v = 0.0_f64;
    let mut digits = 0;
    while let Some(d) = chars.peek().and_then(|c| c.to_digit(16)) {
        v = v * 16.0 + f64::from(d);
        digits += 1;
        chars.next();
    }
    if chars.peek() == Some(&'.') {
        chars.next();
        let mut scale = 1.0 / 16.0;
        while let Some(d) = chars.peek().and_then(|c| c.to_digit(16)) {
            v += f64::from(d) * scale;
            scale /= 16.0;
            digits += 1;
            chars.next();
        }
    }
    if digits == 0 {
        return None;
    }
    if matches!(chars.peek(), Some('p' | 'P')) {
        let exponent: String = chars.skip(1).collect();
        let e = atoi(&exponent);
        if exponent.trim_start_matches(['+', '-']).starts_with(|c: char| c.is_ascii_digit()) {
            v *= 2f64.powi(i32::try_from(e).unwrap_or(if e < 0 { i32::MIN } else { i32::MAX }));
        }
    }
    Some(v)
}

/// The longest prefix of `t` that is a decimal number (digits, point, digits, exponent only when
/// digits follow it), parsed; 0 when there is none.
fn decimal(t: &str) -> f64 {
    let b = t.as_bytes();
    let digits = |from: usize| b[from..].iter().take_while(|c| c.is_ascii_digit()).count();
    let mut end = digits(0);
    let mut mantissa_digits = end;
    if b.get(end) == Some(&b'.') {
        let frac = digits(end + 1);
        mantissa_digits += frac;
        end += 1 + frac;
    }
    if mantissa_digits == 0 {
        return 0.0;
    }
    if matches!(b.get(end), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(b.get(end + 1), Some(b'+' | b'-')));
        let exp = digits(end + 1 + sign);
        if exp > 0 {
            end += 1 + sign + exp;
        }
    }
    t[..end].parse::<f64>().unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn atof_reads_the_leading_number_as_c_does() {
        assert_eq!(atof("None"), 0.0);
        assert_eq!(atof(""), 0.0);
        assert_eq!(atof("  12.5 m/s"), 12.5);
        assert_eq!(atof("-3e2x"), -300.0);
        assert_eq!(atof("7e"), 7.0);
        assert_eq!(atof(".5"), 0.5);
        assert_eq!(atof("."), 0.0);
        assert_eq!(atof("0x1A"), 26.0);
        assert_eq!(atof("0x1p3"), 8.0);
        assert_eq!(atof("-Infinity"), f64::NEG_INFINITY);
        assert!(atof("nan").is_nan());
        // "None" is not "nan": only the three letters n, a, n are
        assert_eq!(atof("Nonsense"), 0.0);
    }

    #[test]
    fn atoi_reads_the_leading_integer() {
        assert_eq!(atoi("None"), 0);
        assert_eq!(atoi(" -42abc"), -42);
        assert_eq!(atoi("3.9"), 3);
        assert_eq!(atoi("+7"), 7);
        assert_eq!(atoi("99999999999999999999999"), i64::MAX);
    }
}

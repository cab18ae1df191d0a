//! Parameters and variables as the storyboard sees them at run time (set and modified by
//! global actions, read by conditions). Ordered by name for deterministic output.
//!
//! Each keeps its declared type, as esmini's ParameterStruct does: a condition compares an
//! integer as integers, a double with SMALL_NUMBER's tolerance, a string as text and a
//! boolean as booleans (TrigByParameter / TrigByVariable::CheckCondition, EvaluateRule), and a
//! modify rule works in the variable's type (VariableAddAction, VariableMultiplyByAction).

use crate::rules::{compare, compare_exact, compare_text};
use openscenario::{ModifyKind, ModifyRule, ParameterDeclaration, ParameterType, Rule};
use std::collections::BTreeMap;

/// The types esmini keeps a typed value of (Parameters::parseParameterDeclarations); the others
/// it reads with an error and compares by no rule of its own.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Integer,
    Double,
    Boolean,
    Text,
    Other,
}

fn kind_of(t: ParameterType) -> Kind {
    match t {
        ParameterType::Integer => Kind::Integer,
        ParameterType::Double => Kind::Double,
        ParameterType::Boolean => Kind::Boolean,
        ParameterType::String => Kind::Text,
        ParameterType::UnsignedInt | ParameterType::UnsignedShort | ParameterType::DateTime => Kind::Other,
    }
}

#[derive(Debug, Clone)]
struct Entry {
    kind: Kind,
    text: String,
}

#[derive(Debug, Clone, Default)]
pub(crate) struct Values {
    map: BTreeMap<String, Entry>,
}

/// What a modify rule did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Modified {
    Done,
    /// No such name, or a number was wanted and the value is none.
    Missing,
    /// A string or boolean: esmini changes nothing.
    NotNumeric,
}

impl Values {
    pub(crate) fn from_declarations(decls: &[ParameterDeclaration]) -> Values {
        Values { map: decls.iter().map(|d| (d.name.clone(), Entry { kind: kind_of(d.parameter_type), text: d.value.clone() })).collect() }
    }

    /// Set a value; false when the name is not declared (the value is still recorded, as text).
    pub(crate) fn set(&mut self, name: &str, value: &str) -> bool {
        let key = name.trim_start_matches('$');
        match self.map.get_mut(key) {
            Some(e) => {
                e.text = value.to_string();
                true
            }
            None => {
                self.map.insert(key.to_string(), Entry { kind: Kind::Other, text: value.to_string() });
                false
            }
        }
    }

    /// `name`'s value against `value` by `rule`, in `name`'s type; `None` when not declared.
    pub(crate) fn compare(&self, name: &str, value: &str, rule: Rule) -> Option<bool> {
        let e = self.map.get(name.trim_start_matches('$'))?;
        Some(match e.kind {
            Kind::Integer => compare_exact(&c_atoi(&e.text), &c_atoi(value), rule),
            Kind::Double => compare(c_atof(&e.text), c_atof(value), rule),
            Kind::Text => compare_exact(e.text.as_str(), value, rule),
            Kind::Boolean => compare_exact(&(e.text == "true"), &(value == "true"), rule),
            Kind::Other => compare_text(&e.text, value, rule),
        })
    }

    /// Apply a modify rule in the value's type: an integer adds the rule's value cut to an
    /// integer, or is multiplied and then cut (C's conversion, toward zero); a double as is.
    pub(crate) fn modify(&mut self, name: &str, rule: &ModifyRule) -> Modified {
        let Some(e) = self.map.get_mut(name.trim_start_matches('$')) else { return Modified::Missing };
        match e.kind {
            Kind::Integer => {
                let v = c_atoi(&e.text);
                let n = match rule.kind {
                    ModifyKind::Add => v.wrapping_add(rule.value as i32),
                    ModifyKind::Multiply => (f64::from(v) * rule.value) as i32,
                };
                e.text = n.to_string();
            }
            Kind::Double => e.text = format_number(apply(c_atof(&e.text), rule)),
            Kind::Text | Kind::Boolean => return Modified::NotNumeric,
            Kind::Other => {
                let Ok(v) = e.text.trim().parse::<f64>() else { return Modified::Missing };
                e.text = format_number(apply(v, rule));
            }
        }
        Modified::Done
    }
}

/// A modify rule on a double.
fn apply(v: f64, rule: &ModifyRule) -> f64 {
    match rule.kind {
        ModifyKind::Add => v + rule.value,
        ModifyKind::Multiply => v * rule.value,
    }
}

/// Whole numbers without a fraction, others as Rust's shortest round trip (exact on reading
/// back, as esmini keeps the double itself beside its text).
fn format_number(n: f64) -> String {
    if n.fract() == 0.0 && n.abs() < 1e15 {
        format!("{}", n as i64)
    } else {
        format!("{n}")
    }
}

/// C's atoi as esmini's strtoi uses it: leading blanks, a sign, then digits up to the first
/// other character; nothing readable is 0 (out of range saturates here; C leaves it undefined).
fn c_atoi(s: &str) -> i32 {
    let t = s.trim_start();
    let (neg, digits) = match t.as_bytes().first() {
        Some(b'-') => (true, &t[1..]),
        Some(b'+') => (false, &t[1..]),
        _ => (false, t),
    };
    let mut v: i64 = 0;
    for b in digits.bytes().take_while(u8::is_ascii_digit) {
        v = (v * 10 + i64::from(b - b'0')).min(i64::from(i32::MAX) + 1);
    }
    let v = if neg { -v } else { v };
    v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

/// C's atof as esmini's strtod uses it: the longest leading part that reads as a number
/// (blanks skipped, a fraction and an exponent allowed); nothing readable is 0.
fn c_atof(s: &str) -> f64 {
    let t = s.trim_start();
    let b = t.as_bytes();
    let mut end = 0;
    if matches!(b.first(), Some(b'+' | b'-')) {
        end = 1;
    }
    let int_digits = b[end..].iter().take_while(|c| c.is_ascii_digit()).count();
    end += int_digits;
    let mut frac_digits = 0;
    if b.get(end) == Some(&b'.') {
        frac_digits = b[end + 1..].iter().take_while(|c| c.is_ascii_digit()).count();
        end += 1 + frac_digits;
    }
    if int_digits + frac_digits == 0 {
        // inf, nan and hex floats are C's too, but no scenario writes them as a value
        return t.parse::<f64>().unwrap_or(0.0);
    }
    if matches!(b.get(end), Some(b'e' | b'E')) {
        let mut k = end + 1;
        if matches!(b.get(k), Some(b'+' | b'-')) {
            k += 1;
        }
        let exp_digits = b.get(k..).map_or(0, |r| r.iter().take_while(|c| c.is_ascii_digit()).count());
        if exp_digits > 0 {
            end = k + exp_digits;
        }
    }
    t[..end].parse::<f64>().unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::{c_atof, c_atoi};

    #[test]
    fn numbers_read_as_c_reads_them() {
        assert_eq!(c_atoi("2.7"), 2);
        assert_eq!(c_atoi(" -12abc"), -12);
        assert_eq!(c_atoi("1e3"), 1);
        assert_eq!(c_atoi("x"), 0);
        assert_eq!(c_atof("1e3"), 1000.0);
        assert_eq!(c_atof("3.5xyz"), 3.5);
        assert_eq!(c_atof("-.5"), -0.5);
        assert_eq!(c_atof("2e"), 2.0);
        assert_eq!(c_atof("abc"), 0.0);
    }
}

//! What an expression evaluates to: a number or a boolean, and how each reads as the other
//! or as the text of a string attribute.

/// The value of an expression or of a parameter inside one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExprValue {
    Num(f64),
    Bool(bool),
}

impl ExprValue {
    pub fn as_num(self) -> f64 {
        match self {
            ExprValue::Num(v) => v,
            ExprValue::Bool(b) => f64::from(u8::from(b)),
        }
    }
    pub fn as_bool(self) -> bool {
        match self {
            ExprValue::Num(v) => v != 0.0,
            ExprValue::Bool(b) => b,
        }
    }
    /// Text form used when an expression feeds a string attribute: integers without a
    /// fractional part, booleans as `true` / `false`.
    pub fn to_text(self) -> String {
        match self {
            ExprValue::Bool(b) => b.to_string(),
            ExprValue::Num(v) if v.fract() == 0.0 && v.abs() < 1e15 => format!("{}", v as i64),
            ExprValue::Num(v) => format!("{v}"),
        }
    }
}

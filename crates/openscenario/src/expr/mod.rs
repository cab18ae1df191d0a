//! `${...}` expressions of OpenSCENARIO 1.2: arithmetic (`+ - * / %`, unary minus),
//! comparisons (`== != < <= > >=`), `and` / `or` / `not`, `true` / `false`, parameters (`$name`)
//! and the standard functions (round, floor, ceil, sqrt, pow, sin, cos, tan, asin, acos, atan,
//! sign, abs, max, min). A tokenizer and a recursive-descent evaluator; errors give the
//! 1-based column inside the expression text.

mod functions;
mod lexer;
mod parser;
mod standard;

pub use parser::{concatenate, evaluate};
pub use standard::beyond_the_standard;

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

/// An expression error at a 1-based character column of the expression text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExprError {
    pub column: usize,
    pub message: String,
}

impl std::fmt::Display for ExprError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "column {}: {}", self.column, self.message)
    }
}

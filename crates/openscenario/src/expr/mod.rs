//! `${...}` expressions of OpenSCENARIO 1.2: arithmetic (`+ - * / %`, unary minus),
//! comparisons (`== != < <= > >=`), `and` / `or` / `not`, `true` / `false`, parameters (`$name`)
//! and the standard functions (round, floor, ceil, sqrt, pow, sin, cos, tan, asin, acos, atan,
//! sign, abs, max, min). A tokenizer and a recursive-descent evaluator; errors give the
//! 1-based column inside the expression text.

mod error;
mod functions;
mod lexer;
mod parser;
mod standard;
mod value;

pub use error::ExprError;
pub use parser::{concatenate, evaluate};
pub use standard::beyond_the_standard;
pub use value::ExprValue;

//! Any `${...}` expression text evaluates to a value or an error, with parameters that are
//! numbers, booleans and strings.
#![no_main]
use libfuzzer_sys::fuzz_target;
use openscenario::expr::{evaluate, ExprValue};

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let mut lookup = |name: &str| -> Result<ExprValue, String> {
        match name.len() % 3 {
            0 => Ok(ExprValue::Num(name.len() as f64 - 2.5)),
            1 => Ok(ExprValue::Bool(name.len() % 2 == 0)),
            _ => Err(format!("unknown parameter {name}")),
        }
    };
    let _ = evaluate(&text, &mut lookup);
});

//! The functions the OpenSCENARIO 1.2 expression grammar lists.

/// Applies `name` to `args`; `Err` is the message (the caller knows the column).
pub(crate) fn call(name: &str, args: &[f64]) -> Result<f64, String> {
    let arity = match name {
        "pow" | "max" | "min" => 2,
        "round" | "floor" | "ceil" | "sqrt" | "sin" | "cos" | "tan" | "asin" | "acos" | "atan" | "sign" | "abs" => 1,
        _ => return Err(format!("unknown function '{name}'")),
    };
    if args.len() != arity {
        return Err(format!("function '{name}' takes {arity} argument(s), got {}", args.len()));
    }
    let a = args[0];
    let v = match name {
        "round" => a.round(),
        "floor" => a.floor(),
        "ceil" => a.ceil(),
        "sqrt" if a < 0.0 => return Err(format!("sqrt of a negative number ({a})")),
        "sqrt" => a.sqrt(),
        "sin" => a.sin(),
        "cos" => a.cos(),
        "tan" => a.tan(),
        "asin" | "acos" if !(-1.0..=1.0).contains(&a) => return Err(format!("{name} of {a} is outside [-1, 1]")),
        "asin" => a.asin(),
        "acos" => a.acos(),
        "atan" => a.atan(),
        "sign" => {
            if a > 0.0 {
                1.0
            } else if a < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        "abs" => a.abs(),
        "pow" => a.powf(args[1]),
        "max" => a.max(args[1]),
        "min" => a.min(args[1]),
        _ => return Err(format!("unknown function '{name}'")),
    };
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{name} gives a non-finite result"))
    }
}

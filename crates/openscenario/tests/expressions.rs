//! Golden tests of `${...}` expressions: values computed by hand, errors with their columns.

use openscenario::expr::{evaluate, ExprValue};

fn params(name: &str) -> Result<ExprValue, String> {
    match name {
        "a" => Ok(ExprValue::Num(3.0)),
        "b" => Ok(ExprValue::Num(-2.5)),
        "flag" => Ok(ExprValue::Bool(true)),
        _ => Err(format!("parameter ${name} is not declared")),
    }
}

fn num(src: &str) -> f64 {
    match evaluate(src, &mut params) {
        Ok(ExprValue::Num(v)) => v,
        other => panic!("{src}: expected a number, got {other:?}"),
    }
}

fn boolean(src: &str) -> bool {
    match evaluate(src, &mut params) {
        Ok(ExprValue::Bool(v)) => v,
        other => panic!("{src}: expected a boolean, got {other:?}"),
    }
}

fn err(src: &str) -> (usize, String) {
    match evaluate(src, &mut params) {
        Err(e) => (e.column, e.message),
        Ok(v) => panic!("{src}: expected an error, got {v:?}"),
    }
}

#[test]
fn arithmetic_and_precedence() {
    assert_eq!(num("1 + 2 * 3"), 7.0);
    assert_eq!(num("(1 + 2) * 3"), 9.0);
    assert_eq!(num("10 - 4 - 3"), 3.0); // left associative
    assert_eq!(num("2 * 3 / 4"), 1.5);
    assert_eq!(num("7 % 4"), 3.0);
    assert_eq!(num("-3 + 5"), 2.0);
    assert_eq!(num("--3"), 3.0);
    assert_eq!(num("-(2 + 3) * 2"), -10.0);
    assert_eq!(num("1.5e2 + .5"), 150.5);
    assert_eq!(num("$a * $b"), -7.5);
    assert_eq!(num("$a - -$b"), 0.5);
    assert_eq!(num("108 / 3.6"), 30.0);
}

#[test]
fn functions() {
    assert_eq!(num("round(2.5)"), 3.0);
    assert_eq!(num("round(-2.5)"), -3.0);
    assert_eq!(num("floor(-1.2)"), -2.0);
    assert_eq!(num("ceil(1.2)"), 2.0);
    assert_eq!(num("sqrt(16)"), 4.0);
    assert_eq!(num("pow(2, 10)"), 1024.0);
    assert_eq!(num("abs($b)"), 2.5);
    assert_eq!(num("sign($b)"), -1.0);
    assert_eq!(num("sign(0)"), 0.0);
    assert_eq!(num("max($a, 4)"), 4.0);
    assert_eq!(num("min($a, $b)"), -2.5);
    assert!((num("sin(pi / 2)") - 1.0).abs() < 1e-15);
    assert!((num("cos(0)") - 1.0).abs() < 1e-15);
    assert!((num("tan(pi / 4)") - 1.0).abs() < 1e-12);
    assert!((num("asin(1)") - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    assert!((num("acos(-1)") - std::f64::consts::PI).abs() < 1e-15);
    assert!((num("atan(1)") - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
    assert_eq!(num("max(min(5, 2 * $a), sqrt(4))"), 5.0);
}

#[test]
fn comparisons_and_logic() {
    assert!(boolean("1 < 2"));
    assert!(!boolean("2 <= 1"));
    assert!(boolean("$a == 3"));
    assert!(boolean("$a != 4"));
    assert!(boolean("$a >= 3 and $b < 0"));
    assert!(boolean("$a > 5 or $b < 0"));
    assert!(boolean("not $a > 5"));
    assert!(!boolean("not $flag"));
    assert!(boolean("true and not false"));
    // `and` binds tighter than `or`.
    assert!(boolean("true or false and false"));
    assert!(!boolean("(true or false) and false"));
}

#[test]
fn errors_with_columns() {
    // Columns are 1-based within the expression text.
    assert_eq!(err("1 +"), (4, "unexpected end of expression, expected a value".to_string()));
    // (expression, column of the error, a fragment of its message)
    let cases = [
        ("2 * (3 + 4", 11, "expected ')' to close '(' at column 5"),
        ("1 + $nope", 5, "$nope is not declared"),
        ("foo(1)", 1, "unknown function 'foo'"),
        ("pow(2)", 1, "takes 2 argument(s), got 1"),
        ("1 / (2 - 2)", 3, "division by zero"),
        ("sqrt(0 - 1)", 1, "sqrt of a negative number"),
        ("3 # 4", 3, "unexpected character '#'"),
        ("1 2", 3, "expected an operator or the end"),
        ("1 + $", 5, "expected a parameter name"),
        ("asin(2)", 1, "outside [-1, 1]"),
    ];
    for (expression, column, fragment) in cases {
        let (col, msg) = err(expression);
        assert_eq!(col, column, "{expression}: {msg}");
        assert!(msg.contains(fragment), "{expression}: {msg}");
    }
    assert_eq!(err("1 / (2 - 2)").1, "division by zero");
}

#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    let src = format!("{}1{}", "(".repeat(2000), ")".repeat(2000));
    let (_, msg) = err(&src);
    assert!(msg.contains("nested deeper"), "{msg}");
    let src = format!("{}1", "-".repeat(3000));
    let (_, msg) = err(&src);
    assert!(msg.contains("nested deeper"), "{msg}");
}

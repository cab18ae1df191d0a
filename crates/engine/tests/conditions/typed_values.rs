//! Parameters and variables keep their declared type, as esmini's ParameterStruct does:
//! a ParameterCondition / VariableCondition compares an integer as integers (the value read by
//! atoi), a string as text, a boolean as booleans (only "true" is true), a double with
//! SMALL_NUMBER's tolerance (TrigByParameter / TrigByVariable::CheckCondition, EvaluateRule);
//! a VariableModifyAction adds an integer's value cut to an integer or multiplies and cuts
//! (VariableAddAction, VariableMultiplyByAction) and leaves a string alone. Fixture
//! `typed_parameters_and_variables.xosc`: six cars at 1 m/s, each sped to 10 m/s by one
//! condition, the modifications at 0.1 s: integer 2 + 1.9 = 3 (Add starts), integer 3 × 1.5 = 4
//! (Mul starts), string "10" > "9" (false: Str stays), boolean true = "1" (false: Bool stays),
//! integer 5 = "5.7" (true: Int starts at once), string "5" + 1 = "6" (the string keeps "5":
//! Text stays). Our earlier engine, comparing every value as a number, got all six wrong.
//! Expected values: esmini 3.6.0 on the fixture (x).

use crate::common::*;

const ROWS: [(&str, f64); 6] = [("Add", 19.1), ("Mul", 39.1), ("Str", 51.0), ("Bool", 71.0), ("Int", 100.0), ("Text", 111.0)];

#[test]
fn parameters_and_variables_compare_and_change_in_their_declared_type() {
    let run = run_fixture_on("typed_parameters_and_variables.xosc", "straight.xodr", 1.0);
    for (name, x) in ROWS {
        let e = at(&run, name, 1.0);
        assert!(close(e.x, x, 1e-6), "{name} at 1 s: x {}, esmini {x}", e.x);
    }
    let warned = run.warnings.iter().any(|w| w.to_string().contains("`VStr` is a string or boolean"));
    assert!(warned, "the string's modify is named: {:?}", run.warnings);
}

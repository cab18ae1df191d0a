//! The tolerance of a condition's rule: esmini's EvaluateRule(double) (OSCCondition.cpp)
//! compares with CommonMini's SMALL_NUMBER, 1e-6 — a strict comparison needs that margin and
//! equality accepts it. Fixture `condition_rules_tolerance.xosc` on `straight.xodr`: five cars at
//! 1 m/s, each sped to 10 m/s by one condition set within 1e-6 of where it would flip:
//! time > 0.9999995 and time ≥ 1.0000005 (both first true at 1.00 s with a margin of 1e-10,
//! at 1.01 s in esmini), time = 1.0000004 (never true with 1e-10, at 1.00 s in esmini), speed
//! < 1.0000005 (true at once with 1e-10, never in esmini), speed = 1.0000005 (at once in
//! esmini, never with 1e-10). Expected values: esmini 3.6.0 on the fixture (x).

use crate::common::*;

const ROWS: [(&str, f64, f64); 10] = [
    ("Gt", 1.01, 11.01),
    ("Gt", 2.0, 20.91),
    ("Ge", 1.01, 31.1),
    ("Ge", 2.0, 41.0),
    ("Eq", 1.01, 51.1),
    ("Eq", 2.0, 61.0),
    ("Lt", 1.01, 71.01),
    ("Lt", 2.0, 72.0),
    ("SpeedEq", 0.01, 90.1),
    ("SpeedEq", 2.0, 110.0),
];

#[test]
fn a_rule_compares_with_esmini_small_number() {
    let run = run_fixture_on("condition_rules_tolerance.xosc", "straight.xodr", 2.0);
    for (name, t, x) in ROWS {
        let e = at(&run, name, t);
        assert!(close(e.x, x, 1e-6), "{name} at {t}: x {}, esmini {x}", e.x);
    }
}

/// The entity conditions' own tolerances are esmini's SMALL_NUMBER too: a time headway is
/// undefined (false) while the triggering entity moves slower than 1e-6 m/s
/// (TrigByTimeHeadway), and an angle within its tolerance plus 1e-6 holds (TrigByAngle).
/// Fixture `entity_conditions_small_number.xosc`: Creeper at 5e-7 m/s behind a standing car
/// (headway > 1 s would start Signal), Angled heading along the road against an angle of
/// 0.1 ± 0.0999995 (would start Flag). esmini starts Flag, not Signal.
#[test]
fn entity_conditions_use_esmini_small_number() {
    let run = run_fixture_on("entity_conditions_small_number.xosc", "straight.xodr", 1.0);
    for (name, t, x) in [("Signal", 0.01, 60.01), ("Signal", 1.0, 61.0), ("Flag", 0.01, 130.1), ("Flag", 1.0, 140.0)] {
        let e = at(&run, name, t);
        assert!(close(e.x, x, 1e-6), "{name} at {t}: x {}, esmini {x}", e.x);
    }
}

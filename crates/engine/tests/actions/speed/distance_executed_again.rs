//! A SpeedAction whose dynamics are a distance, executed again, reads as its distance the time
//! span its first execution computed: esmini's LongSpeedAction::Start turns the distance into a
//! time (2·distance / |v0 + v1|) and stores it in the transition's parameter target
//! (TransitionDynamics::SetParamTargetVal) in place of the distance, which the next Start reads
//! again (GetParamTargetVal). Found by crates/difftest (s36036_00891, a cubic over 62.38 m run
//! three times).
//!
//! Fixture `speed_distance_executed_again.xosc` on straight.xodr: Car at 10 m/s; Faster (two
//! executions, while the speed is under 15 m/s) goes to 20 m/s over 40 m: 2.667 s the first
//! time. Slower sets 10 m/s at 4 s and Faster runs again: over "2.667 m", 0.178 s, which the
//! acceleration limit (10 m/s²) stretches to 1 s — reaching 20 m/s at 5 s, not 6.67 s. esmini
//! 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_distance_speed_change_executed_again_takes_the_first_time_span_as_its_distance() {
    let run = assert_fixture_matches_esmini(
        "speed_distance_executed_again.xosc",
        6.0,
        &[("Car", 3.0, 56.716625, -1.75, 0.0), ("Car", 4.2, 78.906625, -1.75, 0.0), ("Car", 6.0, 111.666625, -1.75, 0.0)],
    );
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
}

//! StandStillCondition on esmini's accumulated clock: `TrigByStandStill` holds once the time
//! since the stand-still stamp is strictly longer than the duration, and ScenarioEngine's clock
//! is a sum of steps, so a duration of whole steps usually holds one step after the duration
//! (fixture `standstill_duration_clock.xosc`, times from esmini 3.6.0's log).

use crate::common::*;

#[test]
fn stand_still_durations_hold_when_esmini_accumulated_clock_says_so() {
    let run = run_fixture_on("standstill_duration_clock.xosc", "straight.xodr", 6.0);
    let expected = [("E0", 0.64), ("E1", 1.08), ("E2", 2.01), ("E3", 2.31), ("E4", 3.43), ("T0", 2.16), ("T1", 2.60), ("T2", 3.53), ("T3", 3.82), ("T4", 4.94)];
    for (event, t) in expected {
        let got = event_time(&run, event, "start").unwrap_or(-1.0);
        assert!(close(got, t, 0.005), "{event} started at {got}, esmini {t}");
    }
}

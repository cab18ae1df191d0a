//! A ReachPositionCondition whose position element has an Orientation child: esmini 3.6
//! (ScenarioReader sets TrigByReachPosition::checkOrientation_) also asks the entity's heading,
//! pitch and roll each to be within 0.05 rad of the position's, as plain differences of angles
//! in [0, 2π). Found by a helper on s65065_00139 (an Orientation h −1.23 that esmini never met).
//!
//! Fixture `reach_position_orientation.xosc` on straight.xodr: Ego drives along lane −1 at
//! heading 0 and passes s 50 at 2.8 s (tolerance 2 m). R0 (no orientation), R1 (absolute h
//! 0.03) and R4 (relative h 0) fire then; R2 (h 0.1) and R3 (h −0.02, read as 6.263) never
//! do. esmini 3.6.0's run.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn reach_position_with_an_orientation_also_asks_the_angles() {
    let run = run_fixture_scenario("reach_position_orientation.xosc", 5.0);
    for fires in ["R0", "R1", "R4"] {
        let t = event_time(&run, fires, "start");
        assert!(t.is_some_and(|t| close(t, 2.8, 1e-9)), "{fires} starts at {t:?}");
    }
    for never in ["R2", "R3"] {
        assert_eq!(event_time(&run, never, "start"), None, "{never}");
    }
    assert_matches_esmini("reach_position_orientation.xosc", &run, 1e-3);
}

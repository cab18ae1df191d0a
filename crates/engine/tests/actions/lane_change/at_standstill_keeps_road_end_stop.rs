//! A lane change claims the longitudinal domain even while its car stands: esmini's
//! LatLaneChangeAction::Step sets the LONGITUDINAL dirty bit before it returns at |speed| <
//! 1e-6, so the default controller skips the car, and ScenarioEngine::step's end-of-road rule
//! keeps a car stopped at a dead end at speed 0 whatever a later SpeedAction asks. The engine
//! let the default controller move it. Found by a helper on s66066_00452.
//!
//! Fixture `lane_change_at_standstill_keeps_road_end_stop.xosc` on straight.xodr: the car
//! stands at the road's end (x 1000) when a lane change starts at 2 s and a SpeedAction to
//! −5 m/s a step later; it stays at x 1000 with speed 0 until the act stops at 5 s, and the
//! lane change never completes. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;
use crate::common::*;

#[test]
fn a_lane_change_at_standstill_keeps_a_car_stopped_at_the_road_end() {
    let run = assert_fixture_matches_esmini(
        "lane_change_at_standstill_keeps_road_end_stop.xosc",
        5.0,
        &[("Ego", 2.0, 1000.0, -1.75, 0.0), ("Ego", 4.5, 1000.0, -1.75, 0.0), ("Ego", 5.0, 1000.0, -1.75, 0.0)],
    );
    assert!(close(at(&run, "Ego", 4.5).speed, 0.0, 1e-9), "speed at 4.5 s: {}", at(&run, "Ego", 4.5).speed);
    assert_eq!(event_time(&run, "A0", "end"), None);
}

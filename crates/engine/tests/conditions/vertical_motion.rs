//! Conditions with direction="vertical" read the entity's vertical velocity and acceleration:
//! esmini's ScenarioEngine::prepareGroundTruth derives them like the horizontal ones, from the
//! change of z (and of that rate) over the step, and a teleport's velocity has no vertical part
//! (TrigByAcceleration::CheckCondition reads GetAccZ, TrigBySpeed / TrigByRelativeSpeed
//! GetVelZ). So a car set on a slope sees a vertical acceleration of its whole climbing rate /
//! dt at the first step, and another at a crest. Found by crates/difftest (s25025_00037 on
//! curves_elevation.xodr). Fixture `vertical_motion_conditions.xosc` on `hill.xodr` (rising at
//! 0.5 to s = 50, then falling): Ego from s 10 at 10 m/s (climbing at 5 m/s), Other standing;
//! each rising-edge event shifts Ego's lane offset. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn vertical_speed_and_acceleration_conditions_follow_esmini() {
    let run = run_fixture_on("vertical_motion_conditions.xosc", "hill.xodr", 6.0);
    // esmini: Lift (vertical acceleration 500 > 100) and Above (relative vertical speed 5 > 4)
    // at 0.01 s; Crest (−1000 < −100) and Climb (vertical speed −5 < −4) at the crest, 4.01 s.
    for (action, t) in [("LiftAction", 0.01), ("AboveAction", 0.01), ("CrestAction", 4.01), ("ClimbAction", 4.01)] {
        let start = event_time(&run, action, "start");
        assert!(start.is_some_and(|s| close(s, t, 1e-9)), "{action}: {start:?}, esmini {t}");
    }
    // (time, x, y, z) of Ego from esmini's trace
    for (t, x, y, z) in [(0.01, 10.1, -1.75, 5.05), (0.02, 10.2, -1.65, 5.1), (4.01, 50.1, -1.65, 24.95), (4.02, 50.2, -1.45, 24.9), (5.0, 60.0, -1.45, 20.0)] {
        let s = at(&run, "Ego", t);
        assert!(close(s.x, x, 1e-6) && close(s.y, y, 1e-6) && close(s.z, z, 1e-6), "at {t}: {s:?}, esmini ({x}, {y}, {z})");
    }
}

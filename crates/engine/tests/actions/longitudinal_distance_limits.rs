//! A LongitudinalDistanceAction's DynamicConstraints, as esmini's
//! ScenarioReader::parseDynamicConstraints reads them with the actor: a limit above the actor's
//! performance is cut to it, a missing one is the performance's. Fixture
//! `long_distance_limits_cut_to_performance.xosc` on straight.xodr, three actors with maxSpeed
//! 12, maxAcceleration 3 and maxDeceleration 6:
//! - Ego, maxSpeed 27 given, chases a lead at 20 m/s and holds 12 m/s;
//! - Ego2, maxAcceleration 9 given, gains 3 m/s² (1.5 m/s in 0.5 s) and holds its own 11;
//! - Ego3, no maxDeceleration given, brakes behind a standing lead at 6 m/s², not unbounded.
//!
//! Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "long_distance_limits_cut_to_performance.xosc";

#[test]
fn the_limits_are_cut_to_the_actors_performance() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert!(close(at(&run, "Ego", 5.0).speed, 12.0, 1e-9), "{:?}", at(&run, "Ego", 5.0));
    assert!(close(at(&run, "Ego2", 0.5).speed, 6.5, 1e-9), "{:?}", at(&run, "Ego2", 0.5));
    let braking = at(&run, "Ego3", 1.0).speed - at(&run, "Ego3", 1.25).speed;
    assert!(close(braking, 1.5, 1e-6), "Ego3 loses {braking} m/s in 0.25 s");
    assert_esmini_pose_at(&run, "Ego", 3.0, 126.235, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego3", 3.0, 519.298677, -1.75, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

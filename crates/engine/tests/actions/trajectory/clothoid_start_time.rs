//! A Clothoid shape whose startTime is above zero, followed with a time reference: esmini 3.6's
//! ClothoidShape::Evaluate takes the start time off twice, s = length · (t − 2·start) /
//! (stop − start), and Spiral::EvaluateDS clamps s to the path. So the entity waits at the
//! path's start until the trajectory time reaches twice the start time, then runs at
//! length / (stop − start), and the action ends at the stop time short of the path's end.
//!
//! Fixture `clothoid_start_time_twice.xosc` on straight.xodr: two 40 m clothoids started at
//! 1 s, one timed relatively (stamps 1–5 s, offset 0.5 s), one absolutely (stamps 2–6 s, offset
//! 0.3 s; its first step falls before the first stamp, which puts it at the far end for one
//! step). The numbers are esmini 3.6.0's run; where esmini runs here the whole run is compared.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn a_clothoid_with_a_late_start_time_waits_at_its_start_for_twice_that_time() {
    let run = run_fixture_scenario("clothoid_start_time_twice.xosc", 20.0);
    // Waiting at the start (s below zero, clamped).
    assert_esmini_pose_at(&run, "AbsLate", 3.7, 20.0, -5.25, 0.0);
    assert_esmini_pose_at(&run, "RelLate", 1.5, 20.0, -1.75, 0.0);
    // Moving, 10 m/s along the clothoid.
    assert_esmini_pose_at(&run, "AbsLate", 5.0, 32.998515, -5.103545, 0.0338);
    assert_esmini_pose_at(&run, "RelLate", 4.0, 44.86174, -0.721913, 0.124002);
    // Ended at the stop time halfway (absolute) or three quarters (relative) along.
    assert_esmini_pose_at(&run, "AbsLate", 5.7, 39.987204, -4.71691, 0.08);
    assert_esmini_pose_at(&run, "RelLate", 5.0, 54.802946, 0.045839, 0.18);
    assert_matches_esmini("clothoid_start_time_twice.xosc", &run, 1e-3);
}

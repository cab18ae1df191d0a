//! A ghost that reaches a dead end during its head start (fixture
//! `ghost_end_of_road_head_start.xosc` on crossing.xodr: head start 1 s, 20 m/s from 15 m before
//! the end of road 2's lane -1, FollowGhostController in position mode). esmini 3.6.0's
//! ScenarioEngine::step stamps an object at a road's end with the simulation time and
//! Object::IsEndOfRoad reads a stamp at or below SMALL_NUMBER as "not there", so while the clock
//! is negative the ghost is stamped again every step and its speed is never zeroed: it keeps
//! reporting 20 m/s until 0.01 s and stops at 0.02 s. The trail's first vertex after that
//! (speed 0) is the Ego's speed point from then on: it brakes at 10 m/s² from 0.21 s to a halt
//! 8.9 m past the road's end. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_end_of_road_head_start.xosc";

#[test]
fn a_ghost_at_a_road_end_keeps_its_speed_until_time_zero_is_passed() {
    let run = run_fixture_scenario(FIXTURE, 10.0);
    // (time, speed) of the ghost, stopped at y = 320 from -0.25 s.
    for (t, v) in [(-0.25, 20.0), (-0.1, 20.0), (0.0, 20.0), (0.01, 20.0), (0.02, 0.0), (1.0, 0.0)] {
        let s = at(&run, "Ego_ghost", t);
        assert!(close(s.speed, v, 1e-9) && close(s.y, 320.0, 1e-9) || t < -0.24, "ghost at {t} s: {s:?}, esmini speed {v}");
    }
    // (time, y, speed) of the Ego.
    for (t, y, v) in [(0.1, 307.0, 20.0), (0.5, 314.535, 17.0), (1.0, 321.76, 12.0), (2.0, 328.71, 2.0), (3.0, 328.945, 0.0)] {
        let s = at(&run, "Ego", t);
        assert!(close(s.y, y, 1e-3) && close(s.speed, v, 1e-3), "Ego at {t} s: {s:?}, esmini y {y} speed {v}");
    }
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

//! ALKS_R157SM_Controller (FSM, override mode) driving into a dead end (fixture
//! `alks_r157_end_of_road.xosc` on crossing.xodr: road 2 lane -1 ends at s = 300, reached at
//! 2 s at 20 m/s). esmini 3.6.0's ScenarioEngine::step checks every object's position status
//! before it steps the controllers, whoever moved the object: stamped at the end at 2.01 s and
//! not moving, the Ego gets speed 0 at 2.02 s; the model, reading that speed, cruises up from 0
//! by 0.02 m/s a step, and is zeroed again the next step. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "alks_r157_end_of_road.xosc";

#[test]
fn a_model_stuck_at_a_dead_end_is_set_to_standstill_every_step() {
    let run = run_fixture_scenario(FIXTURE, 10.0);
    for (t, y, v) in [(1.99, 319.8, 20.0), (2.0, 320.0, 20.0), (2.01, 320.0, 20.0), (2.02, 320.0, 0.02), (3.0, 320.0, 0.02), (4.0, 320.0, 0.02)] {
        let s = at(&run, "Ego", t);
        assert!(close(s.y, y, 1e-9) && close(s.speed, v, 1e-9), "Ego at {t} s: {s:?}, esmini y {y} speed {v}");
    }
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

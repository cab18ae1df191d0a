//! An ACC in override mode moves its entity itself, as esmini's ControllerACC::Step does:
//! `MoveAlongS(currentSpeed * dt)` every step, whether an action moved the entity too (a lane
//! change starts again from its own position, LatLaneChangeAction::Step's `internal_pos_`, so
//! the log shows the ACC's move on top of it: one step's travel ahead); and at the end of the
//! road, ScenarioEngine::step gives an entity that has been there since the step before and did
//! not move speed 0, which the ACC takes as its set speed and brakes to at its deceleration.
//! Fixtures (straight road, Ego's ACC in override mode at 20 m/s, max deceleration 5 m/s²):
//! `acc_override_lane_change.xosc` (a 3 s sinusoidal lane change to lane -2 at t > 1),
//! `acc_override_end_of_road.xosc` (from s = 950 on the 1000 m road). Expected values: esmini
//! 3.6.0 on the same fixtures.

use crate::common::*;

#[test]
fn an_overriding_acc_moves_on_top_of_a_lane_change() {
    let run = run_fixture("acc_override_lane_change.xosc", "straight.xodr");
    // esmini: 0.4 m in the lane change's first step (both moves), then one step's 0.2 m ahead
    // of the action's own position for good (was 0.2 m behind esmini from 1.02 s on)
    for (t, x, y) in [(1.01, 30.2, -1.75), (1.02, 30.6, -1.75), (2.0, 50.176, -2.609), (5.0, 110.074, -5.25), (6.0, 130.074, -5.25)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 2e-3) && close(e.y, y, 2e-3), "t {t}: {e:?}");
    }
}

#[test]
fn an_overriding_acc_brakes_at_the_end_of_the_road() {
    let run = run_fixture("acc_override_end_of_road.xosc", "straight.xodr");
    // esmini: at the road's end (x 1000) from 2.50 s; speed 0 from the engine at 2.52 s, which
    // the ACC takes as its set speed: 5 m/s² down from 20 m/s (was 20 m/s for ever)
    for (t, v) in [(2.5, 20.0), (2.51, 20.0), (2.52, 19.95), (4.0, 12.55), (6.0, 2.55)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, 1000.0, 1e-9) && close(e.speed, v, 1e-6), "t {t}: {e:?}");
    }
}

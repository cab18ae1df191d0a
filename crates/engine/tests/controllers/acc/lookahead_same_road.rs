//! An ACC looks for its lead only within its look-ahead distance — max(50 m, twice the stopping
//! distance) — on its own road as well as through links: esmini's ControllerACC::Step asks
//! Position::Delta with that maximum, which finds nothing farther (`abs(dist) < maxDist`).
//! Fixture `acc_lookahead_same_road.xosc` (straight road): Ego's ACC (set speed 12 m/s, max
//! acceleration 5) from 4 m/s; Lead 70 m ahead in the same lane at 8 m/s: out of reach, so Ego
//! speeds up freely at 0.7 × 5 m/s². Expected values: esmini 3.6.0 on the same fixture (osc2cr
//! followed Lead as a lead vehicle before, at 5 m/s²).

use crate::common::*;

#[test]
fn an_acc_ignores_a_vehicle_beyond_its_look_ahead_on_its_own_road() {
    let run = run_fixture("acc_lookahead_same_road.xosc", "straight.xodr");
    for (t, x, v) in [(0.5, 12.446, 5.75), (2.0, 25.035, 11.0), (6.0, 72.759, 12.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 2e-3) && close(e.speed, v, 6e-3), "t {t}: {e:?}");
    }
}

//! A NaturalDriver in additive mode advances twice per step: esmini's default controller moves
//! the entity by its speed (no override holds it), then ControllerNaturalDriver::Step moves it
//! again by the speed it decides (its MoveAlongS runs whatever the mode). Fixture
//! `natural_driver_additive.xosc` (straight road): Ego at 10 m/s with a NaturalDriver in
//! additive mode (desired speed 20 m/s, maxAcc 2 m/s²), nothing ahead in its lane. Expected
//! values: esmini 3.6.0 on the same fixture (`--fixed_timestep 0.01`).

use crate::common::*;

#[test]
fn an_additive_natural_driver_moves_on_top_of_the_default_controller() {
    let run = run_straight_fixture("natural_driver_additive.xosc", 5.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini's rows (x, speed): 10 + 0.1 (default controller at 10 m/s) + 0.100188 (the
    // driver at 10.0188 m/s) after the first step, and so on.
    for (t, x, v) in [(0.01, 10.200188, 10.01875), (1.0, 31.840151, 11.820371), (2.0, 57.184984, 13.496039), (4.0, 116.94486, 16.231913)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-4) && close(e.speed, v, 1e-4), "Ego at {t}: {e:?}, esmini ({x}, {v})");
    }
}

//! An OpenSCENARIO 1.2 file (fixture `activate_before_1_3_switches_off.xosc`, straight road): a
//! LoomingController (set speed 15 m/s) active from the Init, an ACC in override mode (set speed
//! 20 m/s) assigned at t > 2 without activation, and an ActivateControllerAction naming no
//! controller at t > 3. Before 1.3 esmini switches the looming controller off first
//! (ActivateControllerAction::Start, "only one controller can be active") and activates the
//! most recently assigned one: the ACC alone drives from 3.01 s up to its set speed. (A 1.3
//! file keeps both: `assigned_beside_looming`.) Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn before_1_3_activating_a_controller_switches_off_the_one_active_on_its_domain() {
    let run = run_fixture("activate_before_1_3_switches_off.xosc", "straight.xodr");
    // (time, x, speed); with both controllers stepping: x 107.56 at 6 s, 15 m/s
    let expected = [
        (2.02, 47.730364, 14.998085),
        (3.0, 62.430002, 14.999987),
        (3.02, 62.730352, 15.034988),
        (3.03, 62.881052, 15.069988),
        (4.0, 79.16249, 18.464988),
        (6.0, 118.696046, 19.998613),
    ];
    for (t, x, v) in expected {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.speed, v, 1e-4) && close(e.y, -1.75, 1e-3), "t {t}: {e:?}, esmini x {x} speed {v}");
    }
}

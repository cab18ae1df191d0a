//! Before OpenSCENARIO 1.3 an assigned controller has no name (fixture
//! `assigned_controller_unnamed_before_1_3.xosc`, 1.2, straight road): esmini's ScenarioReader
//! gives the controller of an AssignControllerAction the name of its ObjectController wrapper,
//! which only 1.3 has, and the empty name otherwise. A LoomingController (set speed 15 m/s) is
//! active from the Init; an ACC (override, set speed 20 m/s) called "Acc" in the file is
//! assigned at t > 2; the activation with controllerRef="Acc" at t > 3 finds no controller and
//! does nothing, and the one naming none at t > 5 switches the Looming controller off and the
//! ACC on. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn an_assigned_controller_is_not_found_by_its_own_name_before_1_3() {
    let run = run_fixture("assigned_controller_unnamed_before_1_3.xosc", "straight.xodr");
    // (time, x, speed); the ACC taking over at 3 s would be at 20 m/s by 5 s
    let expected =
        [(3.0, 62.430002, 14.999987), (5.0, 92.427001, 14.999993), (5.02, 92.727351, 15.034993), (6.0, 109.159495, 18.464993), (8.0, 148.693053, 19.998613)];
    for (t, x, v) in expected {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.speed, v, 1e-4), "t {t}: {e:?}, esmini x {x} speed {v}");
    }
}

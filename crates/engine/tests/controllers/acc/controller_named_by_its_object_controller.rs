//! The name an activation finds a controller by (fixture
//! `controller_named_by_its_object_controller.xosc`, OpenSCENARIO 1.3, straight road): the
//! entity's LoomingController (set speed 15 m/s) sits in ObjectController name="Loom", and an
//! ACC (override, set speed 20 m/s) named "Acc" is assigned at t > 2 inside ObjectController
//! name="AccWrapped". esmini's ScenarioReader renames each controller after its wrapper, so the
//! activation of "Acc" at t > 3 finds none and activates nothing, and the activation of
//! "AccWrapped" at t > 5 switches the ACC on beside the Looming controller (1.3 switches none
//! off). Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn a_controller_is_activated_by_its_object_controllers_name() {
    let run = run_fixture("controller_named_by_its_object_controller.xosc", "straight.xodr");
    // (time, x, speed); activating "Acc" at 3 s would give 20 m/s from then on
    let expected =
        [(3.0, 62.430002, 14.999987), (4.0, 77.427231, 14.998785), (5.02, 92.877351, 15.034993), (6.0, 107.560593, 14.997897), (8.0, 137.561508, 14.99969)];
    for (t, x, v) in expected {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.speed, v, 1e-4), "t {t}: {e:?}, esmini x {x} speed {v}");
    }
}

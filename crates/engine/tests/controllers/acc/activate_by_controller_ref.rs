//! An ActivateControllerAction naming its controller (fixture `activate_by_controller_ref.xosc`,
//! OpenSCENARIO 1.3, straight road): a LoomingController (set speed 15 m/s) active from the
//! Init, an ACC in override mode (set speed 20 m/s) assigned at t > 2 without activation, and
//! at t > 3 an activation with `objectControllerRef="Looming"` (the attribute esmini's
//! ScenarioReader reads from a 1.3 file; `controllerRef` before). esmini activates the
//! controller of that name (Object::GetController), not the most recently assigned ACC: the car
//! stays at 15 m/s. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn a_named_activation_activates_that_controller_not_the_last_assigned() {
    let run = run_fixture("activate_by_controller_ref.xosc", "straight.xodr");
    // (time, x, speed); activating the ACC instead: 20 m/s, x 118.70 at 6 s
    let expected = [(3.0, 62.430002, 14.999987), (3.02, 62.730002, 14.999989), (4.0, 77.427231, 14.998785), (6.0, 107.424131, 14.999309)];
    for (t, x, v) in expected {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.speed, v, 1e-4) && close(e.y, -1.75, 1e-3), "t {t}: {e:?}, esmini x {x} speed {v}");
    }
}

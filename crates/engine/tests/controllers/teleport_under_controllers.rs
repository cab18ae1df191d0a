//! A TeleportAction does nothing while any controller in override mode is active on the
//! entity's lateral or longitudinal domain (esmini's TeleportAction::Start:
//! `Object::IsControllerModeOnAnyOfDomains(MODE_OVERRIDE, DOMAIN_MASK_LAT_AND_LONG)`), with each
//! controller's mode as esmini sets it: LoomingController, NaturalDriver and
//! ALKS_R157SM_Controller override unless their `mode` says additive (the Controller base's
//! default), the ACC additive unless it says override (ControllerACC). Fixture
//! `teleport_under_controllers.xosc` (straight road, four cars at 10 m/s, each with one of those
//! controllers activated in the Init, each teleported 400 m ahead at t > 1). Expected values:
//! esmini 3.6.0 on the same fixture.

use crate::common::*;

#[test]
fn a_teleport_is_ignored_under_a_controller_in_override_mode() {
    let run = run_fixture("teleport_under_controllers.xosc", "straight.xodr");
    // esmini at 1.02 s: the three overriding controllers' cars drive on, the ACC's jumps
    for (name, x) in [("Looming", 20.198), ("Natural", 20.2), ("Alks", 210.2), ("Acc", 600.0)] {
        let e = at(&run, name, 1.02);
        assert!(close(e.x, x, 2e-3), "{name}: {e:?}");
    }
    let e = at(&run, "Acc", 3.0);
    assert!(close(e.x, 619.8, 1e-6), "{e:?}");
}

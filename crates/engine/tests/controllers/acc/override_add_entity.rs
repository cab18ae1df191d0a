//! An AddEntityAction places the entity also while its ACC in override mode drives it (esmini's
//! AddEntityAction::Start calls Position::TeleportTo with no override test, unlike
//! TeleportAction::Start). Fixture `acc_override_add_entity.xosc` (straight road): Ego's ACC
//! (override, 20 m/s) at s = 10; Ego is deleted at t > 1 and added back at s = 300 at t > 2.
//! Expected values: esmini 3.6.0 on the same fixture (`--fixed_timestep 0.01`).

use crate::common::*;

#[test]
fn an_added_entity_is_placed_under_an_overriding_acc() {
    let run = run_straight_fixture("acc_override_add_entity.xosc", 6.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini: last row before the deletion at 1.01 s (x 30.2), none until 2.02 s, where the
    // ACC has already moved it one step on from s = 300; then 20 m/s on.
    assert!(close(at(&run, "Ego", 1.01).x, 30.2, 1e-9));
    for (t, x) in [(2.02, 300.2), (2.03, 300.4), (3.0, 319.8), (5.0, 359.8)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-6) && close(e.y, -1.75, 1e-9) && close(e.speed, 20.0, 1e-9), "Ego at {t}: {e:?}");
    }
}

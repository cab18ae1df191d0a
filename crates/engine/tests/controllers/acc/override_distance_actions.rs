//! Under an ACC in override mode the distance and synchronize actions wait (esmini's
//! LongDistanceAction::Step, SynchronizeAction::Step and LatDistanceAction::Step return while
//! `IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LONG)`; LatDistanceAction passes
//! `ControlDomains::DOMAIN_LAT`, value 1, which is the longitudinal mask), and a
//! LateralDistanceAction holds the longitudinal domain (its constructor's domain is that same
//! 1): a LongitudinalDistanceAction starting on the entity ends it. Fixture
//! `acc_override_distance_actions.xosc` (straight road): Ego's ACC (override, 20 m/s) gets a
//! LateralDistanceAction to Target at t > 1 and a LongitudinalDistanceAction (unconstrained,
//! 20 m behind Target) at t > 2.5; Other's ACC (override, 15 m/s) a SynchronizeAction at t > 1.
//! Expected values: esmini 3.6.0 on the same fixture (`--fixed_timestep 0.01`).

use crate::common::*;

#[test]
fn distance_and_synchronize_actions_wait_under_an_overriding_acc() {
    let run = run_straight_fixture("acc_override_distance_actions.xosc", 6.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini: Ego stays in its lane centre at 20 m/s (x = 10 + 20 t), Other at 15 m/s
    // (x = 200 − 15 t), whatever the actions ask.
    for t in [1.5, 2.5, 3.0, 5.0] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, 10.0 + 20.0 * t, 1e-6) && close(e.y, -1.75, 1e-9) && close(e.speed, 20.0, 1e-9), "Ego at {t}: {e:?}");
        let o = at(&run, "Other", t);
        assert!(close(o.x, 200.0 - 15.0 * t, 1e-6) && close(o.speed, 15.0, 1e-9), "Other at {t}: {o:?}");
    }
    // esmini's log: "Stopping object Ego Sideways on conflicting Longitudinal domain(s)" at
    // 2.51 s, when Behind starts; Behind and Meet never end by themselves.
    let ended = |name: &str| run.trace.events.iter().find(|ev| ev.element == name && ev.to == "complete").map(|ev| ev.time);
    assert!(ended("Sideways").is_some_and(|t| close(t, 2.51, 1e-9)), "{:?}", ended("Sideways"));
    assert!(ended("Behind").is_none_or(|t| t > 5.0), "{:?}", ended("Behind"));
    assert!(ended("Meet").is_none_or(|t| t > 5.0), "{:?}", ended("Meet"));
}

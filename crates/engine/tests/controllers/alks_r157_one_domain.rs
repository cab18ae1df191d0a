//! An ALKS_R157SM_Controller activated on the lateral domain only: it operates on both
//! (ControllerALKS_R157SM: the Controller base's domains), so it is active on the one asked for
//! and its Step moves the entity in override mode (`MoveAlongS(speed · dt)`), while the default
//! controller still moves it too, as it leaves alone only an entity whose controller overrides
//! the longitudinal domain (ScenarioEngine::defaultController): the entity travels twice its
//! speed. Fixture `alks_r157_one_domain.xosc` (straight road, two cars at 9 m/s with the
//! Regulation model, one activated laterally only, one longitudinally only). Expected values:
//! esmini 3.6.0 on the same fixture (osc2cr left the lateral-only controller off before).

use crate::common::*;

#[test]
fn an_alks_r157_on_one_domain_moves_the_entity_on_top_of_the_default_controller() {
    let run = run_fixture("alks_r157_one_domain.xosc", "straight.xodr");
    for (name, x1, x5) in [("OneDomain", 118.0, 190.0), ("Longitudinal", 109.0, 145.0)] {
        let (a, b) = (at(&run, name, 1.0), at(&run, name, 5.0));
        assert!(close(a.x, x1, 1e-6) && close(b.x, x5, 1e-6) && close(b.speed, 9.0, 1e-9), "{name}: {a:?} {b:?}");
    }
}

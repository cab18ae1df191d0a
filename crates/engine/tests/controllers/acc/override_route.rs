//! An ACC in override mode moves its entity as esmini's default controller would
//! (ControllerACC::Step calls Object::MoveAlongS, i.e. Position::MoveAlongS with updateRoute):
//! along an assigned route through a junction, not straight on. Found by crates/difftest
//! (m101/s101_00166). Fixture `acc_override_route.xosc` (crossing.xodr): Ego (ACC override,
//! 10 m/s) on road 1 toward the junction with a route turning onto road 4; Free (ACC override,
//! no route) comes from road 2 and goes straight on onto road 4, where it finds Ego ahead and
//! slows. Expected values: esmini 3.6.0 on the same fixture (`--fixed_timestep 0.01`).

use crate::common::*;

/// esmini's rows for Ego (time, x, y, speed): the left turn of the route.
const EGO: [(f64, f64, f64, f64); 4] =
    [(4.0, 10.348609, -0.508639, 10.0), (5.0, 2.701725, -6.815457, 10.0), (6.0, -1.352465, -15.860585, 10.0), (8.0, -1.75, -35.832349, 10.0)];

/// esmini's rows for Free: following Ego once both are on road 4.
const FREE: [(f64, f64, f64, f64); 3] = [(6.0, -1.75, -9.198562, 8.593392), (7.0, -1.75, -17.526617, 8.1771), (8.0, -1.75, -25.68749, 8.185369)];

#[test]
fn an_overriding_acc_follows_its_route_through_a_junction() {
    let run = run_fixture_on("acc_override_route.xosc", "crossing.xodr", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-3);
    assert_esmini_rows(&run, "Free", &FREE, 1e-3);
}

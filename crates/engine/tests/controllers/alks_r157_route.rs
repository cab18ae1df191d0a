//! An ALKS_R157SM_Controller in override mode moves its car by Object::MoveAlongS
//! (ControllerALKS_R157SM::Step), the move of the default controller and the ACC: along an
//! assigned route through a junction (Position::MoveAlongS with updateRoute), not by the
//! straightest arm. Found by crates/difftest (r11 wa-base s25025_00518). Fixture
//! `alks_r157_route.xosc` (crossing.xodr): Ego at 10 m/s on road 1 with a route turning left
//! onto road 4; expected rows: esmini 3.6.0 on the same fixture (main went straight on).

use crate::common::*;

#[test]
fn an_alks_r157_car_follows_its_route_through_a_junction() {
    let run = run_fixture_on("alks_r157_route.xosc", "crossing.xodr", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_rows(
        &run,
        "Ego",
        &[(4.0, 10.348609, -0.508639, 10.0), (5.0, 2.701725, -6.815457, 10.0), (6.0, -1.352465, -15.860585, 10.0), (8.0, -1.75, -35.832349, 10.0)],
        1e-3,
    );
}

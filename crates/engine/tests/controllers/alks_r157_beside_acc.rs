//! An ALKS_R157SM_Controller in override mode moves its car in every step
//! (ControllerALKS_R157SM::Step: MoveAlongS whatever else moved it), as the ACC does. Found by
//! crates/difftest (r11 wa-base s27027_00857, s27027_00866). Fixture `alks_r157_beside_acc.xosc`
//! (straight road): an ACC (override, 15 m/s) drives the car, and at 1 s an
//! AssignControllerAction adds an ALKS R157 controller (Regulation, override) on both domains;
//! in a 1.3 file the ACC stays active beside it and both move the car, 0.3 m per 10 ms step from
//! 1.02 s. Expected rows: esmini 3.6.0 on the same fixture (main moved it once: 0.15 m a step).

use crate::common::*;

#[test]
fn an_alks_r157_beside_an_active_acc_moves_the_car_too() {
    let run = run_fixture("alks_r157_beside_acc.xosc", "straight.xodr");
    assert_esmini_rows(
        &run,
        "Car",
        &[
            (1.00, 65.0, -1.75, 15.0),
            (1.01, 65.15, -1.75, 15.0),
            (1.02, 65.45, -1.75, 15.0),
            (1.03, 65.75, -1.75, 15.0),
            (2.00, 94.85, -1.75, 15.0),
            (4.00, 154.85, -1.75, 15.0),
        ],
        1e-6,
    );
}

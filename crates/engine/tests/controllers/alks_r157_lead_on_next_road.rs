//! An ALKS_R157SM_Controller finds an object ahead on the next road and measures the gap to it
//! across the two roads: Model::Process looks along the road path (Position::Delta forward,
//! within the model's range) and the free space is measured corner by corner, a pair of corners
//! on two roads along the road path between them (Object::FreeSpaceDistanceObjectRoadLane).
//! Found by crates/difftest (r11 wa-base s27027_00473, s27027_00161). Fixture
//! `alks_r157_lead_on_next_road.xosc` (two_roads.xodr): an FSM car in lane -1 and a Regulation
//! car in lane -2 at 25 m/s on road 1, each 45 m behind a lead at 10 m/s just past the start of
//! road 2; both follow their lead from the start (cruise with a target, -4 m/s²). Expected rows:
//! esmini 3.6.0 on the same fixture (main saw no lead until both were on road 2).

use crate::common::*;

#[test]
fn an_alks_r157_car_follows_a_lead_on_the_next_road() {
    let run = run_fixture_on("alks_r157_lead_on_next_road.xosc", "two_roads.xodr", 4.0);
    assert_esmini_x_speed(
        &run,
        &[
            ("FsmEgo", 0.50, 71.99, 23.0),
            ("FsmEgo", 1.00, 82.98, 21.0),
            ("FsmEgo", 2.00, 101.96, 17.0),
            ("FsmEgo", 3.00, 116.94, 13.0),
            ("FsmEgo", 4.00, 128.248, 10.6),
            ("RegEgo", 1.00, 82.98, 21.0),
            ("RegEgo", 2.00, 101.96, 17.0),
            ("RegEgo", 3.00, 116.94, 13.0),
            ("RegEgo", 4.00, 128.044636, 9.797014),
        ],
        1e-5,
    );
}

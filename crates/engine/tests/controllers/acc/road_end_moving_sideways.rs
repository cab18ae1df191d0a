//! esmini's ScenarioEngine::step gives an entity at the end of its road speed 0 only when its
//! velocity is zero (NEAR_ZERO of x, y and z): the velocity of its whole last step, a lateral
//! action's move included, not the ACC controller's own move alone. Found by a helper on
//! s64064_00006 (an ACC car braking at a road end while a LaneOffsetAction still moved it).
//!
//! Fixture `acc_road_end_while_moving_sideways.xosc` on straight.xodr: two ACC cars in
//! override mode (set speed 20 m/s) reach the road's ends at 0.75 s. "Sliding" is moved
//! sideways by a LaneOffsetAction from 0.5 s until about 3.2 s and keeps 20 m/s that long;
//! "Straight" is stopped at once and its ACC brakes (19.9 m/s at 0.77 s). esmini 3.6.0's
//! numbers.

use crate::common::oracle::assert_fixture_matches_esmini;
use crate::common::*;

#[test]
fn an_acc_car_moving_sideways_at_a_road_end_keeps_its_speed() {
    let run = assert_fixture_matches_esmini(
        "acc_road_end_while_moving_sideways.xosc",
        4.0,
        &[("Sliding", 2.0, 1000.0, -1.088124, 0.022357), ("Straight", 2.0, 0.0, 1.75, std::f64::consts::PI)],
    );
    for (t, sliding, straight) in [(0.77, 20.0, 19.9), (1.5, 20.0, 12.6), (3.0, 20.0, 0.088814)] {
        assert!(close(at(&run, "Sliding", t).speed, sliding, 1e-6), "Sliding at {t} s: {}", at(&run, "Sliding", t).speed);
        assert!(close(at(&run, "Straight", t).speed, straight, 1e-6), "Straight at {t} s: {}", at(&run, "Straight", t).speed);
    }
}

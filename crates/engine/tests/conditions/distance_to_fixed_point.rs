//! A DistanceCondition in road or lane coordinates to a fixed point: esmini's
//! Position::Distance(x, y) places the point by a fresh Position (a search of all roads, no
//! current road), never from the entity's road. The engine tried the entity's road first and,
//! where the point lay on it too, measured along it. Found by a helper on s64064_00044.
//!
//! Fixture `distance_to_fixed_point_placed_afresh.xosc` on crossing.xodr: the point (road 110,
//! lane −2, s 15.55) is placed on road 102 by the full search; Car0, on a clothoid trajectory
//! through road 110, has no road path to road 102, so the lateral distance is LARGE_NUMBER and
//! the falling edge starts E3 (a lane offset of 1 m) at 3.05 s, not 4.56 s. esmini 3.6.0's
//! numbers.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn a_fixed_point_is_placed_by_a_search_of_all_roads() {
    let run = run_fixture_scenario("distance_to_fixed_point_placed_afresh.xosc", 14.48);
    let t = event_time(&run, "E3", "start");
    assert!(t.is_some_and(|t| close(t, 3.05, 1e-9)), "E3 starts at {t:?}");
    assert!(close(at(&run, "Car0", 4.0).x, 4.25, 1e-6), "Car0 at 4 s: {:?}", at(&run, "Car0", 4.0));
    assert_matches_esmini("distance_to_fixed_point_placed_afresh.xosc", &run, 1e-3);
}

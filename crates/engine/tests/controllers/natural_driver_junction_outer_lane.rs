//! Which lanes a NaturalDriver may change to, as esmini 3.6.0's
//! ControllerNaturalDriver::AdjacentLanesAvailable decides: by the lane's index in the section
//! (lanes sorted + to −, centre lane included), so the outer lane of a road with right lanes only
//! (index = largest index − number of left lanes) has no left neighbour. Fixture
//! `natural_driver_junction_outer_lane.xosc` (crossing map, connecting road 101: lanes 0, −1,
//! −2): Ego in lane −2 at its desired 10 m/s, a parked car 30 m ahead in its lane, lane −1 free.
//! Expected values: esmini 3.6.0 on the same fixture: no lane change, Ego brakes to a stop behind
//! the parked car.

use crate::common::*;

#[test]
fn the_outer_lane_of_a_right_only_road_has_no_lane_to_change_to() {
    let run = run_fixture_on("natural_driver_junction_outer_lane.xosc", "crossing.xodr", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_eq!(event_time(&run, "LaneChangeAction_0", "start"), None);
    for (t, x, v) in [(1.0, 9.515, 7.0), (2.0, 4.03, 4.0), (3.0, 1.545, 1.0), (6.0, 1.3833, 0.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, 5.25, 1e-6) && close(e.speed, v, 1e-4), "Ego at {t}: {e:?}, esmini ({x}, {v})");
    }
}

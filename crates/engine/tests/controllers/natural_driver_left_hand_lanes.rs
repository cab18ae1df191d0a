//! Which neighbour lane is "left" for a NaturalDriver on a positive lane: esmini 3.6.0's
//! Position::Delta gives the plain lane id difference (b − a, one less across the centre lane)
//! and ControllerNaturalDriver::UpdateSurroundingVehicles files a vehicle left when that times
//! −SIGN(own lane) is 1, right when it is −1. Fixture `natural_driver_left_hand_lanes.xosc`
//! (crossing map, road 1, right-hand traffic): Ego in lane 1 (driving against s) at its desired
//! 10 m/s, a parked car 40 m ahead in lane 1 and another 22 m ahead in lane 2, the only lane it
//! may change to (its right). Expected values: esmini 3.6.0 on the same fixture: the car in lane
//! 2 makes the change impossible and Ego brakes to a stop behind the car in its own lane.

use crate::common::*;

#[test]
fn a_car_in_the_outer_lane_blocks_the_change_of_a_driver_on_a_positive_lane() {
    let run = run_fixture_on("natural_driver_left_hand_lanes.xosc", "crossing.xodr", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_eq!(event_time(&run, "LaneChangeAction_0", "start"), None);
    for (t, x, v) in [(1.0, 211.515, 7.0), (3.0, 203.414153, 1.482765), (5.0, 202.685523, 0.0), (8.0, 202.685523, 0.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, 1.75, 1e-6) && close(e.speed, v, 1e-4), "Ego at {t}: {e:?}, esmini ({x}, {v})");
    }
}

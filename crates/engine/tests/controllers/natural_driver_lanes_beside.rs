//! Which lanes beside it a NaturalDriver may change to, as esmini 3.6.0 decides. Each fixture
//! (crossing map) has Ego at its desired 10 m/s behind a parked car in its lane, and esmini
//! 3.6.0 on the same fixture (`--fixed_timestep 0.01`) changes no lane there: Ego brakes to a
//! stop behind the parked car.
//!
//! - Which side a neighbour is on, for a driver on a positive lane: Position::Delta gives the
//!   plain lane id difference (b − a, one less across the centre lane) and
//!   ControllerNaturalDriver::UpdateSurroundingVehicles files a vehicle left when that times
//!   −SIGN(own lane) is 1, right when it is −1. `natural_driver_left_hand_lanes.xosc` (road 1,
//!   right-hand traffic): Ego in lane 1 (driving against s), the parked car 40 m ahead, another
//!   22 m ahead in lane 2, the only lane it may change to (its right): that car blocks it.
//! - Which lanes are there: ControllerNaturalDriver::AdjacentLanesAvailable goes by the lane's
//!   index in the section (lanes sorted + to −, centre lane included), so the outer lane of a
//!   road with right lanes only (index = largest index − number of left lanes) has no left
//!   neighbour. `natural_driver_junction_outer_lane.xosc` (connecting road 101: lanes 0, −1,
//!   −2): Ego in lane −2, the parked car 30 m ahead, lane −1 free.

use crate::common::*;

/// Run `fixture` on the crossing map: no lane change, and Ego at `y` with esmini's (t, x, speed).
fn brakes_in_its_lane(fixture: &str, y: f64, rows: &[(f64, f64, f64)]) {
    let run = run_fixture_on(fixture, "crossing.xodr", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_eq!(event_time(&run, "LaneChangeAction_0", "start"), None);
    for &(t, x, v) in rows {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-6) && close(e.speed, v, 1e-4), "{fixture}: Ego at {t}: {e:?}, esmini ({x}, {v})");
    }
}

#[test]
fn a_car_in_the_outer_lane_blocks_the_change_of_a_driver_on_a_positive_lane() {
    brakes_in_its_lane(
        "natural_driver_left_hand_lanes.xosc",
        1.75,
        &[(1.0, 211.515, 7.0), (3.0, 203.414153, 1.482765), (5.0, 202.685523, 0.0), (8.0, 202.685523, 0.0)],
    );
}

#[test]
fn the_outer_lane_of_a_right_only_road_has_no_lane_to_change_to() {
    brakes_in_its_lane("natural_driver_junction_outer_lane.xosc", 5.25, &[(1.0, 9.515, 7.0), (2.0, 4.03, 4.0), (3.0, 1.545, 1.0), (6.0, 1.3833, 0.0)]);
}

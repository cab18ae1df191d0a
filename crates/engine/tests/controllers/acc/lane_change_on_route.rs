//! An entity with a route changing lanes is in the target lane from the first step, at the
//! offset still to go (esmini's LatLaneChangeAction::Step re-attaches the position by
//! XYZ2TrackPos only without a route), so its ACC stops following the vehicle in the lane it
//! leaves at once. Fixture `acc_lane_change_on_route.xosc` (straight road): Ego's ACC
//! (override, 20 m/s) with a route along lane −1, following Target (10 m/s) there; at t > 1 a
//! 4 s lane change to lane −2. Expected values: esmini 3.6.0 on the same fixture
//! (`--fixed_timestep 0.01`).

use crate::common::*;

/// esmini's rows (time, x, y, speed): back to the set speed while still mostly in lane −1.
const ESMINI: [(f64, f64, f64, f64); 5] = [
    (1.5, 36.916198, -1.878001, 18.282807),
    (2.0, 46.454547, -2.252883, 19.650466),
    (3.0, 66.322427, -3.486256, 19.990087),
    (5.0, 106.271711, -5.249946, 19.999992),
    (8.0, 166.271709, -5.25, 20.0),
];

#[test]
fn an_acc_on_a_route_leaves_its_lead_when_the_lane_change_starts() {
    let run = run_straight_fixture("acc_lane_change_on_route.xosc", 9.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_rows(&run, "Ego", &ESMINI, 1e-4);
    // esmini's log at 1.5 s: lane −2, offset 3.372 m (the lane change's remaining offset).
    let lane = at(&run, "Ego", 1.5).road;
    assert!(lane.is_some_and(|l| l.lane_id == -2 && close(l.lane_offset, 3.372, 1e-3)), "{lane:?}");
}

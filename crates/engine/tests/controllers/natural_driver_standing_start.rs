//! A NaturalDriver standing still that finds a lane change worth it: esmini 3.6.0's
//! ControllerNaturalDriver::Step only takes the change (target lane, CHANGE_LANE state) above
//! speed 0, but its initiate flag stays set and the LaneChangeAction is injected anyway, towards
//! the target it has while driving: lane 0. Fixture `natural_driver_standing_start.xosc`
//! (straight road): Ego at rest in lane -2 (t = -5.25) behind a parked car 30 m ahead, lane -1
//! free, laneChangeDuration 3 s. Expected values: esmini 3.6.0 on the same fixture
//! (`--fixed_timestep 0.01`): the car slides onto the reference line (t = 0), square to the road
//! while it is too slow for the sideways motion, and keeps accelerating (still driving).

use crate::common::*;

#[test]
fn a_change_found_at_standstill_goes_to_the_reference_line_while_accelerating() {
    let run = run_straight_fixture("natural_driver_standing_start.xosc", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_eq!(event_time(&run, "LaneChangeAction_0", "start"), Some(0.0));
    for (t, x, y, v) in
        [(0.5, 20.00751, -5.205056, 0.487084), (2.0, 20.018418, -3.421666, 1.577844), (4.0, 27.477371, 0.0, 7.547204), (8.0, 78.672378, 0.0, 16.991589)]
    {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, v, 1e-4), "Ego at {t}: {e:?}, esmini ({x}, {y}, {v})");
    }
}

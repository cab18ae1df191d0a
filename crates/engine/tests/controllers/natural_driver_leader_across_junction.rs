//! Whom a NaturalDriver takes for its leader once a car ahead has entered a junction road its
//! own lane does not lead to, as esmini 3.6.0 decides. RoadPath::Calculate takes the last step
//! into the other car's road whatever the lane, and Position::Delta, finding no connecting lane
//! into that road (Road::GetConnectingLaneId gives 0), measures the other car's lane from the
//! reference lane: lane −1 counts as the driver's own lane whatever lane it drives in.
//!
//! `natural_driver_lane_leaving_junction.xosc` (exit_lane.xodr): Ego (desired 20 m/s) in lane −3
//! of road 0, which leads into road 11 only; a car at 10 m/s 50 m ahead in lane −1, which goes
//! on by road 10. From the frame the car is on road 10 (1.0 s) Ego sees it as its leader 40 m
//! ahead and changes to the free lane −2 (esmini 3.6.0, `--fixed_timestep 0.01`).

use crate::common::*;

#[test]
fn a_car_on_a_junction_road_the_lane_does_not_lead_to_is_the_leader() {
    let run = run_fixture_on("natural_driver_lane_leaving_junction.xosc", "exit_lane.xodr", 4.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini's (t, x, y, speed) of Ego.
    for &(t, x, y, v) in &[
        (1.0, 160.0, -7.5, 20.0),
        (1.02, 160.3994, -7.5, 19.97),
        (1.03, 160.5991, -7.499815, 19.97),
        (2.0, 179.903803, -6.047116, 19.97),
        (3.0, 199.800637, -4.50074, 19.97),
        (3.5, 209.787639, -4.5, 19.977649),
    ] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-4) && close(e.speed, v, 1e-5), "Ego at {t}: {e:?}, esmini ({x}, {y}, {v})");
    }
}

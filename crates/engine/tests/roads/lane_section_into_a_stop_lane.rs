//! A lane that goes on, across a lane-section boundary, as a lane of a type the entity does
//! not drive on (no lane link: the same id, here a stop lane) drops the entity into the
//! drivable lane nearest its old lane's centre, its offset kept: esmini's
//! Road::GetLaneInfoByS ("No connecting lane … matching type mask - looking for closest valid
//! lane", LaneSection::GetClosestLaneIdx). Found by crates/difftest (s36036_00526,
//! s27027_00753 on SampleDatabase.xodr: a motorway entry lane of road 143 narrows to nothing
//! and continues as a stop lane; esmini moved the car into lane −4, the engine drove on in
//! the stop lane). Fixture `lane_section_into_a_stop_lane.xosc` on `stop_lane_ahead.xodr`: a
//! 200 m road whose lane −2 (3.5 m, driving) becomes a stop lane at s = 100; Car on lane −2
//! at 10 m/s from s = 90. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const CAR: [(f64, f64, f64, f64); 4] = [(1.0, 100.0, -5.25, 10.0), (1.01, 100.1, -1.75, 10.0), (1.1, 101.0, -1.75, 10.0), (2.0, 110.0, -1.75, 10.0)];

#[test]
fn a_lane_going_on_as_a_stop_lane_drops_the_car_into_the_driving_lane() {
    let run = run_fixture_on("lane_section_into_a_stop_lane.xosc", "stop_lane_ahead.xodr", 2.0);
    assert_esmini_rows(&run, "Car", &CAR, 1e-6);
    let Some(rp) = at(&run, "Car", 2.0).road else { panic!("Car has a road position") };
    assert!(rp.lane_id == -1 && close(rp.lane_offset, 0.0, 1e-9), "{rp:?}");
}

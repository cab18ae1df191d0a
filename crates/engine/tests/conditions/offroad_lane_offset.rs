//! OffroadCondition on a road with a lane offset (esmini's Position::IsOffRoad measures from
//! the centre lane, t less the lane offset) and off the road from the start (Object::IsOffRoad
//! reads a time stamp of 0 as on the road, so the time counts from the next step): fixture
//! `offroad_lane_offset.xosc` on `lane_offset_slope.xodr`, esmini 3.6.0 starts "Off" at 0.51 s.

use crate::common::*;

#[test]
fn off_road_is_measured_from_the_centre_lane_and_noted_after_the_first_step() {
    let run = run_fixture_on("offroad_lane_offset.xosc", "lane_offset_slope.xodr", 2.0);
    let t = event_time(&run, "Off", "start").expect("went off road");
    assert!((0.505..=0.515).contains(&t), "{t}");
}

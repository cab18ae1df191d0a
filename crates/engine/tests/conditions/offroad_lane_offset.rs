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

#[test]
fn past_the_road_end_only_the_road_width_counts() {
    // offroad_past_road_end.xosc on straight.xodr: teleported 5 m before the road's start and
    // 3 m right of the reference line (within the right lanes' 7 m), the entity is on the road
    // for esmini 3.6.0 (Position::IsOffRoad compares t with the width only): BeforeOff never
    // starts. The same scenario with the entity 9 m right starts it at 0.62 s in esmini.
    let run = run_straight_fixture("offroad_past_road_end.xosc", 1.0);
    assert!(event_time(&run, "BeforeMove", "start").is_some_and(|t| close(t, 0.11, 1e-9)));
    assert_eq!(event_time(&run, "BeforeOff", "start"), None);
    let text = std::fs::read_to_string(fixtures().join("offroad_past_road_end.xosc")).expect("fixture reads");
    let aside = run_on(&text.replace(r#"y="-3""#, r#"y="-9""#), "straight.xodr", &engine::Settings { step: 0.01, max_time: 1.0 });
    assert!(event_time(&aside, "BeforeOff", "start").is_some_and(|t| close(t, 0.62, 1e-9)));
}

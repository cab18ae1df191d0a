//! Which road a point off every road is attached to: esmini's Position::XYZ2TrackPos weighs
//! each road by the distance from its nearest lane-0 segment beyond the road's width, plus 3 m
//! where the point lies past the segment's ends, asks the current road first and lets another
//! replace it only when strictly lighter. The engine compared plain distances, so it held a
//! road 3 m too long past its end. Found by a helper on s61061_00724 and s63063_00378 (looming
//! cars driven off a road's end).
//!
//! Fixture `offroad_past_road_end_weighs_more.xosc` on short_and_long.xodr (an 80 m road and a
//! 250 m one beside it, 40 m to the left): a car follows a trajectory on past the short road's
//! end at 10 m/s, and a probe is teleported onto its lane (RelativeLanePosition) at 3, 4.7 and
//! 5 s. At 4.7 s the car is 37 m past the short road's end, 38.25 m beyond the long road's
//! lanes: 40 with the penalty, so it is on the long road, and the probe lands there. esmini
//! 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_point_past_a_road_end_weighs_three_metres_more() {
    assert_fixture_matches_esmini(
        "offroad_past_road_end_weighs_more.xosc",
        6.0,
        &[("Probe", 4.70, 80.0, -1.75, 0.0), ("Probe", 4.71, 117.0, 38.25, 0.0), ("Car", 4.71, 117.1, -1.75, 0.0)],
    );
}

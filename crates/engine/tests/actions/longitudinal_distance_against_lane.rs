//! A LongitudinalDistanceAction from a car facing against its lane to a car on another road:
//! LongDistanceAction::Step measures with Position::Distance in road coordinates, whose road
//! path (RoadPath::Calculate) turns the distance negative, across roads only, when the start
//! position faces against its lane's driving direction (GetHRelativeDrivingDirection past π/2),
//! as it does for SynchronizeAction. Found by a helper on s59059_00549 and s60060_00717.
//!
//! Fixture `longitudinal_distance_against_lane_across_roads.xosc` on westward.xodr (two roads in
//! a line heading π): Car1 in lane 1 of road 1 facing along s (against lane 1's traffic) at
//! 12 m/s keeps 10 m behind Car0, 35 m ahead on road 2. The distance it reads is −35 m, so it
//! brakes (esmini 3.6.0: 10.2 m/s at 0.5 s); read as +35 m it sped up.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_car_facing_against_its_lane_reads_a_car_on_the_next_road_as_behind() {
    let pi = std::f64::consts::PI;
    assert_fixture_matches_esmini(
        "longitudinal_distance_against_lane_across_roads.xosc",
        2.0,
        &[("Car1", 0.5, 124.279, -1.75, pi), ("Car1", 1.0, 119.944, -1.75, pi), ("Car1", 2.0, 115.774, -1.75, pi)],
    );
}

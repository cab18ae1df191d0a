//! A NaturalDriver counts another entity as found only when its road distance is shorter than
//! the look-ahead distance: esmini's ControllerNaturalDriver::UpdateSurroundingVehicles calls
//! Position::Delta(&veh->pos_, diff, true, lookahead_dist_), and Delta sets `found` only when
//! RoadPath::Calculate succeeds and `abs(dist) < maxDist`; an entity not found has dLaneId 0 and
//! ds LARGE_NUMBER. The engine checked the look-ahead only against the distance to the other
//! entity's road (the path frontier), then added the distance along that road, so an entity
//! within the look-ahead radius in a straight line but farther along the roads became the lead
//! and the driver changed lanes at once. Found by crates/difftest (s62062_00890).
//!
//! Fixture `natural_driver_look_ahead_along_roads.xosc` on hairpin.xodr (a 100 m straight road, two right lanes, then
//! a half circle of radius 10 linked directly): Car2 (NaturalDriver, look-ahead 30) starts on
//! road 1 lane -1 at s 90, Ped3 walks at 0.76 m/s on road 2 lane -1 at s 25, 27.2 m away in a
//! straight line but 35 m along the roads. The pedestrian is found only once the road distance
//! drops under 30 m, so the lane change to lane -2 starts at 0.29 s, not at 0. esmini 3.6.0's
//! numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_natural_driver_ignores_an_entity_farther_along_the_roads_than_its_look_ahead() {
    assert_fixture_matches_esmini(
        "natural_driver_look_ahead_along_roads.xosc",
        2.01,
        &[("Car2", 0.28, 95.166560, -1.750000, 0.0), ("Car2", 0.5, 97.508239, -1.789015, 6.246899), ("Car2", 1.0, 102.599895, -1.928150, 0.093136)],
    );
}

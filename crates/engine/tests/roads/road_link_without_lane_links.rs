//! Where a road links to the next road but the entity's lane has no lane link there, the
//! entity goes on all the same: esmini's Position::MoveToConnectingRoad ("No connection …
//! trying move to closest lane") puts it on the next road's drivable lane nearest the t it
//! had (SetTrackPos at the contact point) and resets its lane offset to 0, an off-road entity
//! too. Found on narrowing.xodr while building the fixture of world_point_beside_a_road_end
//! (the engine stopped at the road's end); multi_intersections, SampleDatabase and
//! lane_offset_intersection have such links. Fixture `road_link_without_lane_links.xosc` on
//! `narrowing.xodr` (road 1, lanes 3.5 m, then road 2, lanes 3 m, no lane links): Car on
//! lane −1 at offset −0.5, Wide 13.25 m beyond lane −1's centre, both at 10 m/s. Expected
//! values: esmini 3.6.0 on the fixture.

use crate::common::*;

const CAR: [(f64, f64, f64, f64); 3] = [(1.0, 100.0, -2.25, 10.0), (1.01, 100.1, -1.5, 10.0), (2.0, 110.0, -1.5, 10.0)];
const WIDE: [(f64, f64, f64, f64); 3] = [(0.02, 100.0, -15.0, 10.0), (0.03, 100.1, -1.5, 10.0), (2.0, 119.8, -1.5, 10.0)];

#[test]
fn a_lane_without_a_link_goes_on_in_the_nearest_lane_of_the_next_road() {
    let run = run_fixture_on("road_link_without_lane_links.xosc", "narrowing.xodr", 2.0);
    assert_esmini_rows(&run, "Car", &CAR, 1e-6);
    assert_esmini_rows(&run, "Wide", &WIDE, 1e-6);
}

//! A road whose start links to another road's start, the entity's lane with no lane link
//! there: esmini's Position::MoveToConnectingRoad takes its closest-lane arm ("No connection …
//! trying move to closest lane") and returns before it turns the heading round for a
//! start-to-start link, so the entity keeps its heading relative to the road. The rest of the
//! step goes into the new road from the contact point; the next step moves it the way it now
//! faces, back across the link by the lane link there: a U-turn. Seen on
//! lane_offset_intersection (a car driving its zero-width lane −1 of road 1 against s reaches
//! road 3). Fixture `start_to_start_unlinked.xosc` on `start_to_start_unlinked.xodr`: road 1
//! along +x from the origin, road 2 along −x from it, starts linked, road 1's lane −1 without
//! a link; Car on lane −1 at offset 0.5 (y −1.25) facing −x at 10 m/s. Expected values:
//! esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn an_unlinked_lane_across_a_start_to_start_link_keeps_the_heading_relative_to_the_road() {
    let run = run_fixture_on("start_to_start_unlinked.xosc", "start_to_start_unlinked.xodr", 2.0);
    // (entity, time, x, y, heading) from esmini's trace: on road 2's lane −1 (y 1.75) facing +x
    // after the link, then back onto road 1's lane 1.
    let rows = [
        ("Car", 0.5, 0.0, -1.25, std::f64::consts::PI),
        ("Car", 0.51, -0.1, 1.75, 0.0),
        ("Car", 0.52, 0.0, 1.75, 0.0),
        ("Car", 1.0, 4.8, 1.75, 0.0),
        ("Car", 2.0, 14.8, 1.75, 0.0),
    ];
    assert_esmini_poses(&run, &rows, 1e-6, 1e-6);
    assert_esmini_rows(&run, "Car", &[(1.0, 4.8, 1.75, 10.0)], 1e-6);
}

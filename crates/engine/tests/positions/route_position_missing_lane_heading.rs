//! A RoutePosition whose lane does not exist on the route's road at pathS: esmini's
//! Position::SetRouteLanePosition → SetLanePos → SetLanePosMode sets the road and s, then finds
//! no lane with that id (LOG_ERROR "Lane id -1 does not exist on road ...") and returns before
//! Lane2Track/Track2XYZ and before lane_id_ is set, which stays 0; SetHeadingRelative(0) then
//! leaves x = y = h = 0. In the first step the default controller's MoveAlongS puts the car on
//! lane 0 (Track2XYZ), facing the road heading plus its relative heading 0, i.e. the route's way
//! along that road. A RelativeLanePosition from such a car moves dsLane along the lane direction
//! with esmini's SIGN, which counts lane 0 as a positive lane (CommonMini `SIGN(X) ((X<0)?-1:1)`).
//! The engine kept the world heading 0 it was placed with, and took lane 0's sign as 0 (no move).
//! Found by crates/difftest (s61061_00309).
//!
//! Fixture `route_position_missing_lane_heading.xosc` on tee_lht.xodr (left-hand traffic): Car0 is placed at
//! pathS 40, lane -1 of a route from road 1 lane -1 (towards the junction) to road 3 lane 1, which
//! is 10 m into connecting road 101, a left-hand traffic connecting road with lanes 1 and 2 only;
//! it drives at 5 m/s, from 0.01 s on lane 0 of road 101 facing 3.644 (road heading, turning with
//! the road). Car1 is placed at dsLane -3 from Car0 (road 101 s 7; in left-hand traffic a positive
//! lane runs along s) and drives at 3 m/s. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_route_position_on_a_missing_lane_faces_the_road_on_lane_zero() {
    assert_fixture_matches_esmini(
        "route_position_missing_lane_heading.xosc",
        2.01,
        &[
            ("Car0", 0.0, 0.0, 0.0, 0.0),
            ("Car0", 0.01, 10.367640, -2.472375, 3.644093),
            ("Car0", 1.0, 6.367225, -5.366223, 3.891593),
            ("Car1", 0.0, 13.142044, -1.212546, 3.491593),
        ],
    );
}

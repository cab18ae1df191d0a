//! A RoadPosition on a lane that drives against s, as esmini 3.6 places it (OSCPositionRoad:
//! without an orientation, or without h, or with a relative one, the heading is relative to
//! the road's reference direction — not the lane's driving direction, unlike a LanePosition;
//! only an absolute h is taken as it is). Fixture `road_position_against_lane.xosc`
//! (straight.xodr; cars on lane 1 with each kind of orientation, one on lane −1, one placed
//! beside the first); the numbers are esmini 3.6.0's run of it, and where esmini runs here the
//! whole run is compared too.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use std::f64::consts::PI;

#[test]
fn road_positions_face_along_the_road_unless_an_absolute_heading_says_otherwise() {
    let run = run_fixture_scenario("road_position_against_lane.xosc", 10.0);
    // Lane 1 drives against s, yet without an orientation the car faces +s and drives on.
    assert_esmini_pose_at(&run, "Left", 3.0, 130.0, 1.75, 0.0);
    assert_esmini_pose_at(&run, "Right", 3.0, 130.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "LeftAbsolute", 3.0, 270.0, 1.75, PI);
    assert_esmini_pose_at(&run, "LeftAbsoluteNoH", 3.0, 530.0, 1.75, 0.0);
    assert_esmini_pose_at(&run, "LeftRelativeHalfTurn", 3.0, 670.0, 1.75, PI);
    // Placed relative to Left: ahead and to the left of a car facing +s.
    assert_esmini_pose_at(&run, "Beside", 0.0, 105.0, 3.75, 0.0);
    assert_matches_esmini("road_position_against_lane.xosc", &run, 1e-3);
}

//! A NURBS control point given as a WorldPosition without h just past a road end has heading 0:
//! OSCPositionWorld → SetInertiaPosMode(h = NaN, H_REL) → XYZ2TrackPos; inside a road the
//! heading becomes the road heading, but past the end (closestPointInside false, "Same point")
//! EvaluateHPR() keeps the fresh absolute h_ = 0. esmini's NurbsShape::EvaluateInternal blends
//! every control point's GetH() into the trajectory heading, so the heading turns towards 0 on
//! the last stretch. The engine gave such a control point the road heading (plus lane drift)
//! wherever it projected. Found by crates/difftest (s62062_00480).
//!
//! Fixture `nurbs_control_point_past_road_end.xosc` on straight_south.xodr (one road from (0, 0) heading
//! south, 1,000 m): Car0 drives on lane 1 at 10 m/s; from 0.5 s a FollowTrajectoryAction
//! (position mode, no timing) follows an order-3 NURBS of four control points, the first and
//! third with h 4.712, the second (3, -965) and the last (1.75, -1000.01, 1 cm past the road end)
//! without h. From about 2.8 s the heading leaves the road heading (4.71) and reaches 6.18 by
//! 5 s. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_nurbs_control_point_without_heading_past_a_road_end_has_heading_zero() {
    assert_fixture_matches_esmini(
        "nurbs_control_point_past_road_end.xosc",
        6.01,
        &[("Car0", 2.0, 2.778946, -964.865769, 5.083215), ("Car0", 4.0, 2.606728, -984.849482, 5.606275), ("Car0", 5.0, 2.064853, -994.833024, 6.184378)],
    );
}

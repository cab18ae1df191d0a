//! A rigid road-frame LateralDistanceAction on a banked road shifts along the normal of the
//! reference line's own heading, and the default move judges the new heading against it too:
//! LatDistanceAction::GetDesiredRoadPos uses Position::GetRoadH() (Geometry::EvaluateDS, no
//! turn from a changing superelevation), and the relative heading that decides forward or
//! backward is taken from GetHRoad(). The engine used the lane pose's heading, which a changing
//! roll turns slightly: the jump straight across the road (3π/2 exactly) then counted as
//! backward and the car drove back. Found by a helper on s75075_00192.
//!
//! Fixture `lateral_distance_jump_on_banked_road.xosc` on a map of ours, banked_gently.xodr
//! (roll growing by 0.002 rad per metre): Ego jumps 1.6 m right of Ref at once and drives on
//! along +s (the whole run within 1 mm; its heading on the bank then differs by a milliradian,
//! the known 3D-heading family). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_jump_keeps_driving_forward() {
    assert_fixture_matches_esmini("lateral_distance_jump_on_banked_road.xosc", 2.0, &[("Ego", 0.01, 80.095, -3.327546, 4.712390)]);
}

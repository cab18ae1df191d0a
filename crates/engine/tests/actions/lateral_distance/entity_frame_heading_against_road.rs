//! The entity-frame LateralDistanceAction turns by the angle from the actor's heading to the
//! target line (LatDistanceAction::Step: GetAngleDifference with Object::pos_.GetH()); where
//! the two lie exactly opposite that angle is ±π and its sign decides the turn. GetH() holds
//! the bits of the last write of the orientation (Position::EvaluateHPR): after an absolute
//! one (SetInertiaPos, SetHeading) the road's rotation composed with GetAngleDifference(h,
//! road), in [−π, π]; after a move along the lane (SetLanePos, relative heading) composed with
//! the relative heading held in [0, 2π). So a car facing exactly against a road along π holds
//! 0 after a teleport and 2π once it has moved along its lane, and turns the other way.
//! The engine read its own heading (in [0, 2π)); reading always the absolute form (3af96f6,
//! reverted) was right after teleports and wrong after moves. Found by a helper on
//! s72072_00345 and s73073_00227, with the fixture of 3af96f6 (s70070_00320).
//!
//! Fixtures on opposite_roads.xodr (road 1 along −x) and tee_lht.xodr; esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

/// The actor drives road 1 facing +x (against it) from 0 s; at 0.5 s it keeps 3.32 m beside
/// Ref: esmini turns it right (heading 6.093685 at 1 s).
#[test]
fn moved_along_its_lane_it_holds_two_pi() {
    assert_fixture_matches_esmini(
        "lateral_distance_entity_frame_moved_against_road.xosc",
        2.0,
        &[("Actor", 1.0, 347.169227, -1.981752, 6.093685), ("Actor", 2.0, 356.397094, -5.677059, 5.714685)],
    );
}

/// The same, teleported by a WorldPosition just before the action starts: esmini turns it left.
#[test]
fn teleported_it_holds_zero() {
    assert_fixture_matches_esmini("lateral_distance_entity_frame_teleported_against_road.xosc", 2.0, &[("Actor", 2.0, 359.197094, 2.677059, 0.5685)]);
}

/// Car0 heads +y, Car1 −y 3.5 m to the side, both placed by world positions; from 0.5 s Car0
/// keeps 0.65 m to Car1's right (maxAcceleration 3): esmini turns Car0 left.
#[test]
fn opposite_headings_along_y() {
    assert_fixture_matches_esmini(
        "lateral_distance_entity_frame_opposite_headings.xosc",
        3.0,
        &[("Car0", 0.52, -1.7503, -264.8, 1.573797), ("Car0", 2.0, -5.046694, -250.496185, 2.017797)],
    );
}

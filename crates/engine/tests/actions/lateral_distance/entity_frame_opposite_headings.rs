//! The entity-frame LateralDistanceAction reads both headings as esmini's positions hold them
//! (Object::pos_.GetH()): along a road along y they lie a micro-radian off the nominal heading,
//! and where actor and reference face exactly opposite ways that decides the sign of the angle
//! between them (±π), so which way the actor turns. Found by a helper on s70070_00320.
//!
//! Fixture `lateral_distance_entity_frame_opposite_headings.xosc` on tee_lht.xodr: Car0 heads
//! +y, Car1 −y 3.5 m to the side; from 0.5 s Car0 keeps 0.65 m to Car1's right (maxAcceleration
//! 3). esmini turns Car0 left (heading 1.573797 at 0.52 s, x −5.047 at 2 s); the nominal
//! headings turned it right. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn opposite_headings_compare_as_esmini_positions_hold_them() {
    assert_fixture_matches_esmini(
        "lateral_distance_entity_frame_opposite_headings.xosc",
        3.0,
        &[("Car0", 0.52, -1.7503, -264.8, 1.573797), ("Car0", 2.0, -5.046694, -250.496185, 2.017797)],
    );
}

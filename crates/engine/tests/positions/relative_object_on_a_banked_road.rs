//! A RelativeObjectPosition on a banked road, from an entity a WorldPosition put there facing
//! against the road. Two esmini rules meet:
//! - The entity's pitch and roll are what its placement composed (Position::EvaluateHPR), with
//!   GetPOffset reading the relative heading the position held before: 0 for a position made
//!   afresh, so facing against the road the entity is pitched the other way until its first
//!   move composes it again. RotateVec3d turns (dx, dy, dz) by that attitude.
//! - The new position is set absolute (SetInertiaPosMode: the entity's heading, pitch and roll),
//!   then EvaluateRelation runs EvaluateHPR once more in the position's SET mode: the road's
//!   rotation composed with the heading's plain difference from the road's, the relative pitch
//!   plus GetPOffset and the relative roll found against the road there.
//!
//! Fixture `relative_object_banked_world_against.xosc` on `banked.xodr` (roll 0.01·s): Ego by
//! a WorldPosition at s = 50 facing π; Beside 10 m ahead of it and 3.5 m to its left in the
//! Init; Later teleported to the same spot relative to Ego at 1.01 s, after Ego moved. Before,
//! Beside landed 0.06 m off and faced 0.02 rad off; Later faced 0.002 rad off. Found by
//! crates/difftest (s32032_00747 on pitch_by_super_elevation.xodr: 0.49 m at the start).
//!
//! Beyond the road's end XYZ2TrackPos leaves the road's pitch and roll at 0, but GetPOffset
//! still reads the rate of the roll there: PastStart, put 12 m before the road's start relative
//! to Ego, keeps Ego's pitch and roll plus that pitch, and Marker, placed relative to
//! PastStart, turns its offsets by them (0.38 m off before). Found by crates/difftest
//! (s31031_00462: a pedestrian placed relative to a truck beyond the road's end, 2.6 m off).
//! Expected values: esmini 3.6.0 on the fixture (moving on, esmini keeps Beside's relative
//! roll in its heading, which the engine's lane following does not compose: `attitude.rs`).

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_relative_object_position_on_a_banked_road_takes_the_attitude_esmini_composes() {
    assert_fixture_matches_esmini(
        "relative_object_banked_world_against.xosc",
        2.0,
        &[
            ("Ego", 0.0, 50.0, 1.75, 3.151151),
            ("Beside", 0.0, 40.001978, -1.417103, 3.164117),
            ("Later", 1.02, 29.901978, -1.310116, 3.132381),
            ("Later", 2.0, 29.901978, -1.310116, 3.132381),
            ("PastStart", 0.0, -11.987665, 4.667834, 3.151151),
            ("Marker", 0.0, -6.922938, 2.083497, 3.151151),
        ],
    );
}

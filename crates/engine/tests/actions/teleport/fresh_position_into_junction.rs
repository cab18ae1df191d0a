//! A teleport to a position given in the world (relative to an entity, or absolute) is
//! attached to a road by a Position made afresh: esmini's TeleportTo evaluates the action's own
//! Position (EvaluateRelation → SetInertiaPosMode → XYZ2TrackPos), which has no current road,
//! so neither the entity's road nor the roads directly connected to it are preferred; where
//! connecting roads overlap, the first in the file containing the point takes it. The entity's
//! own road was asked first, and the nearest lane centre chose among the rest. Found by
//! crates/difftest (s36036_00865 and s36036_00909 on the generated crossing).
//!
//! Fixture `teleport_relative_object_into_junction.xosc` on crossing.xodr: Jumper drives east on
//! lane 1 of road 3 at 25.27 m/s and at 1 s jumps 35.13 m ahead and 3.72 m left of itself, into
//! the junction where straight connecting road 101 (lane −1) and left-turning 111 (lane −2)
//! both contain the point: esmini takes 101 and Jumper goes on straight at y 1.97; before, 111's
//! lane −2 turned it. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_teleport_into_overlapping_connecting_roads_takes_the_first_in_the_file() {
    assert_fixture_matches_esmini(
        "teleport_relative_object_into_junction.xosc",
        3.0,
        &[("Jumper", 1.01, -7.27, 1.97, 0.0), ("Jumper", 1.5, 5.1123, 1.97, 0.0), ("Jumper", 3.0, 43.0173, 1.97, 0.0)],
    );
}

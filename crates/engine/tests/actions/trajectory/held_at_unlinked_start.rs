//! A trajectory that holds its entity exactly at a road's start, where the road has no
//! predecessor: esmini places the follower from world coordinates (Position::SetInertiaPos →
//! XYZ2TrackPos), whose SetLongitudinalTrackPos sets POS_STATUS_END_OF_ROAD at an end without a
//! link element (s within SMALL_NUMBER of it) even though the point lies on the road. Standing
//! there, flagged in an earlier step, the entity is stopped by ScenarioEngine::step ("object at
//! end of road and not moving, enforce zero speed"), so a SpeedAction ramping up later never gets
//! it going. Before, the engine flagged only a point beyond the end, and the car drove off
//! (9.9 m from esmini at 3.56 s).
//!
//! Fixture `trajectory_held_at_unlinked_start.xosc` on straight.xodr: AtStart follows an untimed
//! polyline from (0, −1.75) at speed 0 from 0.5 s, then speeds up sinusoidally from 1 s; Inside,
//! placed 0.5 m into the road by a teleport, speeds up the same way and drives off in both.
//! Found by crates/difftest (s31031_00801 on pitch_by_super_elevation.xodr). The numbers are
//! esmini 3.6.0's run.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn an_entity_held_at_a_road_start_without_predecessor_stays_stopped() {
    assert_fixture_matches_esmini(
        "trajectory_held_at_unlinked_start.xosc",
        4.0,
        &[("AtStart", 1.0, 0.0, -1.75, 0.0), ("AtStart", 3.0, 0.0, -1.75, 0.0), ("Inside", 3.0, 5.918147, -5.25, 0.0)],
    );
}

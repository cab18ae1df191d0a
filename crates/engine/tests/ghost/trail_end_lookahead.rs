//! FollowGhostController in `position` mode when the steering look-ahead reaches past the
//! ghost's trail (ControllerFollowGhost::Step with PolyLineBase::FindClosestPoint,
//! FindPointAhead and Evaluate): the steering point's segment index — the last vertex once it
//! ran past the end — is where the next nearest-point search starts; from the last vertex no
//! segment is searched and the old arc length stays, so the nearest point sticks near the
//! trail's end and the speed point is the ghost's latest sample.
//!
//! Fixture `ghost_position_lookahead_past_trail_end.xosc` on straight.xodr: head start 1 s at
//! 15 m/s, default look-aheads (steering 1 s · speed = the whole 15 m lead), the ghost speeds
//! up to 30 m/s from 1.5 s and moves 0.8 m right. The Ego speeds up as soon as the ghost's
//! latest sample does (a vertex every 0.2 s), about a second before it reaches the spot where
//! the ghost did, and ends 0.2 m right of its lane centre, not 0.8 m. Numbers from esmini
//! 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_position_lookahead_past_trail_end.xosc";

#[test]
fn the_speed_point_is_the_ghosts_latest_sample_once_the_steering_point_runs_past_the_trail() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    // At 2 s the ghost's own speed-up (from 1.5 s) is 15 m behind it; the Ego already gains.
    assert!(at(&run, "Ego", 2.0).speed > 15.05, "{}", at(&run, "Ego", 2.0).speed);
    assert_esmini_pose_at(&run, "Ego", 3.0, 76.317987, -1.939574, 6.279231);
    assert_esmini_pose_at(&run, "Ego", 5.0, 123.357191, -1.967271, 0.000022);
    assert_esmini_pose_at(&run, "Ego", 10.0, 272.930009, -1.967021, std::f64::consts::TAU); // esmini: 6.283185
    assert!(close(at(&run, "Ego", 5.0).speed, 28.401229, 1e-3), "{}", at(&run, "Ego", 5.0).speed);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

//! FollowTrajectoryAction on polylines as esmini 3.6 runs them (FollowTrajectoryAction::Start,
//! Step and Move; PolyLineShape::FinalizeVertices, CalculatePolyLine and Evaluate;
//! PolyLineBase::EvaluateSegmentByLocalS; ScenarioReader's FollowTrajectoryAction):
//! - the heading turns over whole segments in the `follow` mode and across corners in the
//!   `position` mode, between vertex headings that are the ones a position gives explicitly,
//!   else the direction of the segment leaving the vertex;
//! - vertices within 0.1 m of the one kept before are merged (the player's traj_filter), or
//!   kept as a stand-still when the next distinct one is more than a second later;
//! - `follow` mode times a polyline by constant accelerations from the entity's speed,
//!   braking to a stop early where a segment has too much time; the time lookup walks the
//!   vertices as written (stamps out of order, a missing stamp as 0), a vertex's speed
//!   carrying on into a stand-still;
//! - the action ends when the trajectory time plus the TimeReference offset passes the last
//!   stamp; absolute time reads esmini's summed clock; a trajectory spanning no time is
//!   followed without its time reference.
//!
//! Fixtures `trajectory_timing.xosc` (eight cars side by side on straight.xodr, one case each)
//! and `trajectory_unordered_stamps.xosc` (stamps out of order, the run ending with the
//! action: it ended at t = 0 before). The numbers are esmini 3.6.0's runs of them; where esmini
//! runs here the whole runs are compared too, headings included.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn polyline_headings_timing_and_filtering_are_esmini_s() {
    let run = run_fixture_scenario("trajectory_timing.xosc", 20.0);
    // Explicit vertex headings: the follow mode turns towards the next one over the segment,
    // the position mode holds each vertex's (0.17 from 50 m on).
    assert_esmini_pose_at(&run, "HeadingsFollow", 4.0, 39.825, 1.719, 0.0835);
    assert_esmini_pose_at(&run, "HeadingsPosition", 6.0, 59.9, -4.5, 0.17);
    // Without them the follow mode turns from one segment's direction to the next.
    assert_esmini_pose_at(&run, "CornersFollow", 2.5, 24.9, -16.0, 0.1291);
    // Braking: the merged vertices near 45 m and the stop; the offset of 2 s ends it early.
    assert_esmini_pose_at(&run, "Brake", 4.0, 44.0, -24.0, 0.0);
    assert_esmini_pose_at(&run, "Brake", 6.0, 45.0, -24.0, 0.0);
    // The stand-still vertex keeps the entity moving at 10 m/s (esmini's vertex speed).
    assert_esmini_pose_at(&run, "Stand", 4.0, 39.9, -32.0, 0.0);
    assert_esmini_pose_at(&run, "Stand", 9.0, 69.8, -32.0, 0.0);
    assert_esmini_pose_at(&run, "Unordered", 6.0, 69.933, -37.0, 0.0);
    assert_esmini_pose_at(&run, "Partial", 6.0, 30.0, -48.0, 0.1489);
    assert_esmini_pose_at(&run, "OnePoint", 6.0, 10.0, -56.0, 0.0);
    assert_matches_esmini("trajectory_timing.xosc", &run, 1e-3);
}

#[test]
fn a_trajectory_with_stamps_out_of_order_runs_to_its_end() {
    let run = run_fixture_scenario("trajectory_unordered_stamps.xosc", 40.0);
    // Without a time reference the stamps do not matter: the run ends with the action at
    // 7.04 s, as esmini's does (it ended at once before).
    assert!(close(run.trace.end_time(), 7.04, 1e-9), "ends at {}", run.trace.end_time());
    assert_esmini_pose_at(&run, "Ego", 4.0, 39.79, -0.281, at(&run, "Ego", 4.0).h);
    assert_matches_esmini("trajectory_unordered_stamps.xosc", &run, 1e-3);
}

//! Headings of positions on lanes whose centre drifts sideways (a sloped lane offset, a
//! widening lane), as esmini 3.6 sets them: a relative heading (and none) is the road's
//! direction plus the relative angle plus the drift atan(dt/ds) of the lane centre
//! (Position::EvaluateHPR: GetHRelative() + GetHOffset()); an absolute one is taken as it is.
//! The entity kept its drift only once it moved (esmini's heading holds it from the start), so
//! entities placed relative to it landed elsewhere. Fixture `lane_drift_headings.xosc`
//! (`lane_offset_slope.xodr`: lane offset slope 0.05, lane −2 widening by 0.01 per metre);
//! the numbers are esmini 3.6.0's run of it, and where esmini runs here the whole run is
//! compared too, headings included.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn placed_headings_include_the_lane_drift() {
    let run = run_fixture_scenario("lane_drift_headings.xosc", 10.0);
    assert_esmini_pose_at(&run, "Left", 0.0, 150.0, 9.25, 3.191551);
    assert_esmini_pose_at(&run, "Right", 0.0, 50.0, 0.75, 0.049958);
    assert_esmini_pose_at(&run, "RightTurned", 0.0, 100.0, 3.25, 0.249958);
    assert_esmini_pose_at(&run, "Outer", 0.0, 60.0, -2.3, 0.04497);
    assert_esmini_pose_at(&run, "OuterAbsolute", 0.0, 120.0, 0.4, 0.1);
    assert_esmini_pose_at(&run, "Road", 0.0, 200.0, 6.0, 0.04497);
    // Placed relative to a drifting entity: rotated by its heading, drift included.
    assert_esmini_pose_at(&run, "Beside", 0.0, 58.1648, -2.346132, 0.049958);
    assert_esmini_pose_at(&run, "Behind", 0.0, 50.0, -2.75, 0.04497);
    // Moving on keeps the heading.
    assert_esmini_pose_at(&run, "Right", 2.0, 60.0, 1.25, 0.049958);
    assert_matches_esmini("lane_drift_headings.xosc", &run, 1e-3);
}

//! On a road whose laneOffset is not constant, esmini's Position::XYZ2TrackPos takes s from lane
//! 0's OSI points: it projects the point on the lane-0 polyline and interpolates s between the
//! two OSI points along their normals. Lane 0 is tilted by atan(laneOffset'(s)) against the
//! reference line, so a point t metres from lane 0 gets an s about t·laneOffset' smaller than
//! its exact projection. It shows where s is read back: LatLaneChangeAction::Start copies the
//! position and the first Step's SetLanePos(track, lane, s, offset) puts the car at that s. The
//! engine projected a position with a current road exactly on the reference line, so the lane
//! change started from the true s. Found by crates/difftest (s63063_00689).
//!
//! Fixture `lane_offset_s_after_trajectory_jump.xosc` on lane_offset_slope.xodr (laneOffset 0.05·s): Car0 starts on
//! lane -2 at s 10 at 10 m/s; from 0.5 s a FollowTrajectory (follow mode) drives it on a polyline
//! along the centre of lane -2; at 2.0 s a LaneChangeAction to lane -1 (linear, 2 s) starts and
//! stops the trajectory. In the first lane-change step the car goes 0.16 m back in x, to the s
//! interpolated on lane 0. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lane_change_after_a_trajectory_on_a_sloped_lane_offset_starts_from_lane_zero_s() {
    assert_fixture_matches_esmini(
        "lane_offset_s_after_trajectory_jump.xosc",
        3.51,
        &[("Car0", 2.01, 24.988014, -4.000479, 0.039979), ("Car0", 2.02, 24.824644, -3.978122, 0.225193), ("Car0", 3.0, 34.474563, -1.787100, 0.225193)],
    );
}

//! A free-space RelativeClearanceCondition measures each bounding-box corner at the s that
//! XYZ2TrackPos gives it (Object::FreeSpaceDistanceObjectRoadLane maps every corner with
//! `XYZ2TrackPos(x, y, 0)`): interpolated on the road's lane-0 OSI segment between the segment
//! ends' normals, not the exact projection on the reference line. The two part where lane 0
//! runs off the reference line, as under a laneOffset. Found by a helper on s60060_00935
//! (lane_offset_intersection), where the clearance fell three steps early.
//!
//! Fixture `relative_clearance_corners_on_lane_offset.xosc` on lane_offset_slope.xodr (lane 0
//! drifting left 5 cm per metre): Fast (lane −2, 14 m/s) overtakes Slow (lane −1, 8 m/s) and
//! slows to 3 m/s once the area 4 m before and behind it is clear. esmini 3.6.0 starts the
//! event at 2.21 s; with the exact projection it started at 2.20 s.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn clearance_corners_take_the_s_xyz2trackpos_interpolates() {
    assert_fixture_matches_esmini(
        "relative_clearance_corners_on_lane_offset.xosc",
        4.0,
        &[("Fast", 2.2, 176.8, 2.956, 0.04497), ("Fast", 4.0, 182.31, 3.20395, 0.04497), ("Slow", 4.0, 182.0, 7.35, 0.049958)],
    );
}

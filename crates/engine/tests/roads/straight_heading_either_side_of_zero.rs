//! esmini's OSI points hold the heading as its geometry gives it, the piece's start heading
//! taken into [0, 2π). XYZ2TrackPos calls a segment straight when its two vertices' headings
//! differ by less than 1e-5, so a straight road whose pieces point a hair either side of 0
//! (hdg 8e-10, then −8e-10, read as 2π − 8e-10) looks curved there; the normals of that
//! "curve" are parallel, GetIntersectionOfTwoLineSegments refuses them, and every point on the
//! segment is put at its first vertex. Found on s66066_00194 (Junction_with_building0's
//! junction road 101, three near-straight spirals that esmini reads as lines).
//!
//! Fixture `world_position_on_straight_heading_either_side_of_zero.xosc` on
//! straight_heading_either_side_of_zero.xodr (a 100 m road: a line at hdg 8e-10 to 60 m, then
//! one at −8e-10; OSI points at 0, 50 and 100 m): three cars placed by world position at
//! x 20, 80 and 62 m. Near stays at s 20; Far and Off are put at s 50 and drive on from there.
//! esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_straight_segment_across_heading_zero_puts_points_at_its_first_vertex() {
    assert_fixture_matches_esmini(
        "world_position_on_straight_heading_either_side_of_zero.xosc",
        2.0,
        &[("Near", 0.01, 20.1, -1.7, 0.0), ("Far", 0.01, 50.1, -1.7, 0.0), ("Off", 0.01, 50.1, -5.0, 0.0), ("Far", 1.0, 60.0, -1.7, 0.0)],
    );
}

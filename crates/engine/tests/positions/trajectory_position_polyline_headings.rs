//! A TrajectoryPosition on a polyline faces as the vertex its segment starts at: esmini reads
//! the trajectory for the position alone (OSCPositionTrajectory), and a polyline whose
//! interpolation no FollowTrajectoryAction has set keeps PolyLineBase's INTERPOLATE_NONE, so
//! nothing is blended across corners (a followed polyline blends them in the `position` mode).
//! The lateral offset t is taken across that heading.
//!
//! Fixture `trajectory_position_polyline_headings.xosc` on straight.xodr: vertices heading
//! 0, 0.4, 0.4, 0; the numbers are esmini 3.6.0's run of it.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn trajectory_position_on_a_polyline_takes_the_segment_start_vertex_heading() {
    let run = run_fixture_scenario("trajectory_position_polyline_headings.xosc", 2.0);
    let esmini = [
        // 0.5 m past the corner at the second vertex: its heading, not a blend with the first.
        ("PastCorner", 0.0, 31.048366, -13.195896, 0.4),
        // 1.2 m before the third vertex: still the second vertex's heading.
        ("BeforeCorner", 0.0, 47.065943, 5.903206, 0.4),
        ("MidSegment", 0.0, 20.0, 8.5, 0.0),
    ];
    for (name, t, x, y, h) in esmini {
        assert_esmini_pose_at(&run, name, t, x, y, h);
    }
    assert_matches_esmini("trajectory_position_polyline_headings.xosc", &run, 1e-3);
}

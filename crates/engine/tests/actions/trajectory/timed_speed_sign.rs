//! A timed trajectory's speed is negative while the entity faces away from the path:
//! FollowTrajectoryAction::Start gives the start speed the sign of how the heading the vertices
//! give lies to the path (speedSign: more than π/2 off is −1), and Move multiplies every
//! speed it derives by headingDirection, the same test between the entity's heading before the
//! move and the path's own direction where it stood (RMTrajectory::GetHTrue: exactly at a
//! vertex, the segment that ends there). The engine derived the speed from the distance along
//! the path only. The sign matters once the trajectory ends: the default controller drives on
//! at that speed, so a car facing against the path backs on. Found by a helper on
//! s69069_00581.
//!
//! Fixtures on difftest_straight.xodr, esmini 3.6.0's numbers:
//! - `timed_trajectory_faces_against_path.xosc`: vertices facing west (h 3.1416) on a path
//!   running east, timed relatively from 0.5 s: −10 m/s throughout, and after the end (4.5 s)
//!   the car backs on east, at x 165 at 6 s (the engine: +10 m/s, driving west from x 150).
//! - `timed_trajectory_turns_back_past_heading.xosc`: vertices facing east, the last segment
//!   turning back west (absolute timing): the speed turns negative at 1.52 s, one step after
//!   the vertex at 1.5 s, and the car backs on west after the end (x 84.93 at 5 s).

use crate::common::oracle::assert_fixture_matches_esmini;
use crate::common::*;

/// The heading the fixture's vertices give, as written (not π).
#[allow(clippy::approx_constant)]
const VERTEX_H: f64 = 3.1416;

#[test]
fn vertex_headings_against_the_path_make_the_speed_negative() {
    let run = assert_fixture_matches_esmini(
        "timed_trajectory_faces_against_path.xosc",
        6.0,
        &[("Car0", 2.0, 125.0, -5.25, VERTEX_H), ("Car0", 4.52, 150.2, -5.25, VERTEX_H), ("Car0", 6.0, 165.0, -5.25, VERTEX_H)],
    );
    for t in [1.0, 4.0, 6.0] {
        assert!(close(at(&run, "Car0", t).speed, -10.0, 1e-9), "speed at {t} s: {}", at(&run, "Car0", t).speed);
    }
}

#[test]
fn a_segment_turning_back_past_the_heading_makes_the_speed_negative_one_step_after_its_vertex() {
    let run = assert_fixture_matches_esmini(
        "timed_trajectory_turns_back_past_heading.xosc",
        6.0,
        &[("Car0", 3.0, 105.0, -3.75, 0.0), ("Car0", 5.0, 84.9252, -3.25, 0.0)],
    );
    let v = 10.0f64.hypot(1.0);
    assert!(close(at(&run, "Car0", 1.51).speed, v, 1e-3), "speed at 1.51 s: {}", at(&run, "Car0", 1.51).speed);
    assert!(close(at(&run, "Car0", 1.52).speed, -v, 1e-3), "speed at 1.52 s: {}", at(&run, "Car0", 1.52).speed);
}

//! A clothoid spline and a clothoid followed with relative timing from an initial distance
//! offset: esmini 3.6 starts the trajectory clock at the time the shape's one-metre polyline
//! gives that distance (RMTrajectory::GetTime after Position::SetTrajectoryS), and those
//! vertices are timed `first + (s / length) · last` — `last` the clothoid's stopTime, the
//! spline's last segment's timeStart (ClothoidShape and ClothoidSplineShape::CalculatePolyLine)
//! — while the shape is then evaluated by time segment by segment. So the entity jumps from
//! the offset to where that start time puts it, here 10 m back, and goes on from there.
//!
//! Fixture `trajectory_offset_start_time.xosc` on straight.xodr: a spline of 40 m (stamps 0 and
//! 2 s) and 40.6 m (end 4 s), and a 40 m clothoid (stamps 1–3 s), both started at 1 s 20 m in.
//! The numbers are esmini 3.6.0's run; where esmini runs here the whole run is compared.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_relatively_timed_clothoid_started_at_an_offset_runs_from_its_polyline_time() {
    assert_fixture_matches_esmini(
        "trajectory_offset_start_time.xosc",
        20.0,
        &[
            // The first step after the start: about 10 m along, not 20.
            ("SplineOffset", 1.02, 30.12539, -1.706602, 0.01283),
            ("ClothoidOffset", 1.02, 30.199558, -5.179255, 0.020808),
            ("SplineOffset", 2.0, 49.689235, -0.655815, 0.110476),
            ("ClothoidOffset", 2.0, 49.787204, -4.71691, 0.08),
            // After the trajectories' ends, going on along their final headings.
            ("SplineOffset", 4.5, 98.108416, 14.246316, 0.403),
            ("ClothoidOffset", 4.5, 99.787204, -4.71691, 0.08),
        ],
    );
}

//! A clothoid or clothoid spline followed with a time reference whose offset puts the
//! trajectory time before its first stamp: esmini 3.6 evaluates the shape at its end while the
//! time is outside the stamps' range (ClothoidShape::Evaluate, ClothoidSplineShape::Evaluate:
//! "Requested time … outside range"), so the entity waits at the far end, then jumps back when
//! the time comes in range.
//!
//! Fixture `clothoid_time_before_first_stamp.xosc` on straight.xodr: a spline timed
//! relatively (scale 1.2, offset −0.6 s) and a clothoid timed absolutely (offset −1.5 s), both
//! started at 1 s. The numbers are esmini 3.6.0's run; where esmini runs here the whole run
//! is compared, headings included.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn a_clothoid_timed_before_its_first_stamp_waits_at_its_end() {
    let run = run_fixture_scenario("clothoid_time_before_first_stamp.xosc", 20.0);
    assert_esmini_pose_at(&run, "SplineEarly", 1.2, 88.471656, 9.766074, 0.35);
    assert_esmini_pose_at(&run, "ClothoidEarly", 1.2, 76.963363, 8.625504, 0.72);
    assert_esmini_pose_at(&run, "SplineEarly", 3.0, 43.827943, -1.185251, 0.07106);
    assert_esmini_pose_at(&run, "ClothoidEarly", 3.0, 42.476945, -4.491181, 0.10125);
    assert_matches_esmini("clothoid_time_before_first_stamp.xosc", &run, 1e-3);
}

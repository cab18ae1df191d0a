//! NURBS headings as esmini 3.6 computes them (NurbsShape::EvaluateInternal and
//! CalculatePolyLine): when the first control point's position gives a heading, every heading
//! along the curve is blended from the control points' headings by their rational basis
//! weights — a control point without one brings its road's direction — instead of following
//! the curve; otherwise the heading follows the curve. The same in the `position` and `follow`
//! modes and for a TrajectoryPosition.
//!
//! Fixture `nurbs_control_point_headings.xosc` on straight.xodr; the numbers are esmini 3.6.0's
//! run of it; where esmini runs here the whole run is compared, headings included.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn nurbs_headings_are_blended_from_the_control_points_when_the_first_gives_one() {
    let run = run_fixture_scenario("nurbs_control_point_headings.xosc", 20.0);
    // The first control point faces 1.2 rad, the others the road (0) or 0.3: the car turns
    // from 1.2 towards them while the curve itself runs nearly straight. Without a heading on
    // the first control point ("Curve") the heading follows the curve.
    let esmini = [
        ("Blend", 0.5, 14.970928, -1.047214, 0.690149),
        ("Blend", 3.0, 39.862784, -0.740511, 0.097762),
        ("BlendFollow", 1.0, 19.919789, -3.965397, 0.351666),
        ("Curve", 2.0, 29.899922, 3.533618, 6.268564),
        ("Placed", 0.0, 34.890951, -10.467275, 0.098312),
    ];
    for (name, t, x, y, h) in esmini {
        assert_esmini_pose_at(&run, name, t, x, y, h);
    }
    assert_matches_esmini("nurbs_control_point_headings.xosc", &run, 1e-3);
}

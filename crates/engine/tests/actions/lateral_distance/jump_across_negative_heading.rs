//! A road-frame LateralDistanceAction without dynamic constraints jumps the actor across the
//! road along the road's normal (LatDistanceAction::Step: `(−sin, cos)(GetRoadH()) · error`);
//! GetRoadH reads the geometry's heading through Geometry::GetHdg, wrapped into [0, 2π), so a
//! road written with a negative hdg gives the normal of the wrapped angle, whose bits differ.
//! The heading the jump leaves then lies at 3π/2 from the road within a few ulps, and those
//! bits decide which way the default controller drives on. Found by a helper on s73073_00391.
//!
//! Fixture `lateral_distance_jump_across_negative_heading.xosc` on negative_heading.xodr (one
//! road, hdg −1.0471975567816514): the actor jumps 3.07 m to the left of Ref at 0 s and drives
//! on along s (s 50.1 at 0.01 s); with the written hdg's normal it drove back. esmini 3.6.0's
//! numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_jump_uses_the_wrapped_road_heading() {
    assert_fixture_matches_esmini(
        "lateral_distance_jump_across_negative_heading.xosc",
        0.5,
        &[("Actor", 0.01, 137.649784, -49.092361, std::f64::consts::FRAC_PI_6), ("Actor", 0.5, 140.099784, -53.335886, 5.235988)],
    );
}

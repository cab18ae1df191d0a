//! The rigid LateralDistanceAction heads along its jump measured to the desired point as
//! esmini's XYZ2TrackPos holds it: LatDistanceAction::Step sets the heading to the atan2 from
//! where the entity was to `desired_pos`, and XYZ2TrackPos keeps the x and y it was given ("Set
//! given X, Y overriding calculated ones"), not the point the lane position gives back. Straight
//! across a road along x the jump's x difference is exactly 0, the heading exactly 3π/2, which
//! IsAngleForward counts as forward; the point taken back from the lane position (s added to
//! the road's start x) differs in the last bit, and its heading a hair past 3π/2 drove the
//! entity backward. Found by crates/difftest (s33033_00730 on the generated crossing).
//!
//! Fixture `lateral_distance_jump_square_across.xosc` on crossing.xodr: Jumper, 15.23 m behind
//! Reference on lane 1 of road 1 (along +x) and facing +x at 27.98 m/s, is told at 0 s to keep
//! 5.29 m to Reference's left (continuous, no dynamics): at 0.01 s it has jumped to y −3.54,
//! heading 3π/2, and moved 0.28 m forward in the same step; then it drives on along +x.
//! Before the rule it moved back (x 249.54, then heading π). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_jump_straight_across_a_road_along_x_heads_at_three_right_angles_and_drives_forward() {
    assert_fixture_matches_esmini(
        "lateral_distance_jump_square_across.xosc",
        1.0,
        &[("Jumper", 0.01, 250.0998, -3.54, 4.71239), ("Jumper", 0.02, 250.3796, -3.54, 0.0), ("Jumper", 1.0, 277.8, -3.54, 0.0)],
    );
}

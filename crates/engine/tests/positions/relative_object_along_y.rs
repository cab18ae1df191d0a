//! A RelativeObjectPosition turns (dx, dy) by the heading the reference's position holds
//! (Position::EvaluateRelation: rel_pos_->GetH()), which EvaluateHPR's gimbal guard puts a
//! micro-radian off a heading along ±y: a point 600 m ahead lands 0.6 mm aside. Small as it
//! is, an OffroadFollower whose lead then lies exactly behind it reads the side from it
//! (GetAngleOfVector nudges a |x| below 1e-6 to 1e-6), and turns that way. The engine turned
//! by the nominal heading. Found by a helper on s73073_00976.
//!
//! Fixture `relative_object_along_y_gimbal_guard.xosc` on straight_north.xodr (one road along
//! +y): Car0 on lane −1 at 20 m/s; Car1, an OffroadFollower, 31.65 m ahead of it (so Car0 is
//! exactly behind) at 5 m/s; Car2 600 m ahead. esmini: Car2 at x 1.7494 (not 1.75), Car1
//! turns right and is at (0.809, 32.164) at 4 s, where the nominal heading turned it left,
//! to x 2.691. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_offsets_turn_by_the_held_heading() {
    let run = assert_fixture_matches_esmini(
        "relative_object_along_y_gimbal_guard.xosc",
        4.0,
        &[("Car1", 1.0, 7.441048, 59.062276, 0.377505), ("Car1", 4.0, 0.808909, 32.16382, 2.58715)],
    );
    // the placement itself, below the comparison's millimetre
    let car2 = crate::common::at(&run, "Car2", 0.0);
    assert!((car2.x - 1.7494).abs() < 1e-5, "{car2:?}");
}

//! A LoomingController's held lane on a banked road: esmini's XYZ2TrackPos (lockOnLane_)
//! divides the held lane's t by the cosine of the roll the position still holds, the road's at
//! the position before the move ("compensate for banking"), and takes the lane at that t, so
//! on a steep bank the held lane slides outward. The engine left the division out. Found by a
//! helper on s66066_00683 (velodrome).
//!
//! Fixture `looming_lane_lock_on_steep_bank.xosc` on steep_bank.xodr (a straight road banked
//! by 1 rad, six lanes on the right): the looming car, placed in lane −2, is in lane −6 within
//! 0.02 s and drives on there. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_held_lane_is_found_at_its_t_over_the_cosine_of_the_roll() {
    assert_fixture_matches_esmini(
        "looming_lane_lock_on_steep_bank.xosc",
        3.0,
        &[("Ego", 1.0, 69.68856, -6.004363, 6.154682), ("Ego", 3.0, 109.376569, -10.250563, 6.26597)],
    );
}

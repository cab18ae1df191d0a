//! An OffroadFollower places its car with the roll absolute: ControllerOffroadFollower::Step
//! calls SetInertiaPosMode with Z_ABS | H_ABS | P_REL | R_ABS (roll 0), so on a banked road
//! without slope the heading stays the one its vehicle model drives with; the engine placed
//! the car as a plain world position, which turns the heading by the bank. Found by a helper
//! on s67067_00387.
//!
//! Fixture `offroad_follower_roll_absolute_on_bank.xosc` on steep_bank.xodr: Car1 follows Car0
//! from a world position; esmini 3.6.0's numbers (the engine: heading 0.0744 at 0 s where
//! esmini has 0.1371).

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_bank_does_not_turn_the_followers_heading() {
    assert_fixture_matches_esmini(
        "offroad_follower_roll_absolute_on_bank.xosc",
        3.0,
        &[("Car1", 1.5, 50.2439, -0.4382, 6.2695), ("Car1", 3.0, 72.3344, -0.8916, 6.2673)],
    );
}

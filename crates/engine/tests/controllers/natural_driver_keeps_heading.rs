//! A NaturalDriver acts on the longitudinal domain only (esmini's Controller::Activate skips
//! the lateral one for it), so nothing aligns the car's heading: Position::MoveAlongS keeps
//! the heading relative to the road, and the car drives on turned as it was placed. The engine
//! reset the turn at every move of the driver outside its own lane changes. Found by a helper
//! on s64064_00596.
//!
//! Fixture `natural_driver_keeps_heading_from_road.xosc` on straight.xodr: "Turned" is placed
//! at absolute heading 0.5, "Back" at 1.99 (past a right angle, so it drives against s); both
//! keep their headings for 3 s while the drivers speed them up. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_natural_driver_keeps_the_heading_it_was_placed_with() {
    assert_fixture_matches_esmini(
        "natural_driver_keeps_heading_from_road.xosc",
        3.0,
        &[("Turned", 2.0, 67.500041, -1.75, 0.5), ("Back", 2.0, 382.499959, -1.75, 1.99), ("Back", 3.0, 370.382738, -1.75, 1.99)],
    );
}

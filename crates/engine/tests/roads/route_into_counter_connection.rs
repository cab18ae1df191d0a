//! A car with a route that enters a junction by a counter connection (the reverse of one the
//! junction lists, which esmini's CheckJunctionConnection adds for a road the file does not
//! name as incoming, with the contact point flipped) enters at that connection's contact
//! point, as Position::MoveToConnectingRoad always does; the engine took the contact from the
//! road links, which the geometry may contradict. Found by a helper on s68068_00534.
//!
//! Fixture `route_into_counter_connection.xosc` on a map of ours, counter_contact.xodr:
//! esmini 3.6.0 enters the connecting road at its start and drives on at heading 2π (the
//! engine: at its end, turned back, 9.8 m away at 1.21 s).

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_counter_connection_is_entered_at_its_contact_point() {
    assert_fixture_matches_esmini("route_into_counter_connection.xosc", 2.5, &[("Car1", 1.5, 3.0, -1.75, 0.0), ("Car1", 2.5, 13.0, -1.75, 0.0)]);
}

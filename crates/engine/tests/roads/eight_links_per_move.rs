//! One move crosses at most eight road links: esmini's Position::MoveAlongS follows `max_links`
//! (8) links, checking where the rest of the move lands at the top of each pass, so a move that
//! needs an eighth link stays where it entered the eighth road (its SetLanePos at the contact
//! point), with status OK. Found by crates/difftest (s60060_00296: a car at 3.5e11 m/s on
//! circular_road that the engine, allowing 16 links, left at its old s on another road).
//!
//! Fixture `move_crosses_at_most_eight_links.xosc` on ring.xodr (four roads in a loop: 100 m,
//! a half circle, 100 m, a half circle): both cars start at road 0 s 30. From 0.51 s Car2 moves
//! 1,500 m a step, landing on the seventh road it enters and stopping at the eighth in the next
//! step; Car1 moves 1,676.64 m a step, which would land 50 m into the eighth road, and stays at
//! its start. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_move_needing_an_eighth_link_stays_where_it_enters_the_eighth_road() {
    assert_fixture_matches_esmini(
        "move_crosses_at_most_eight_links.xosc",
        0.61,
        &[
            ("Car1", 0.52, 0.0, -1.75, 0.0),
            ("Car1", 0.61, 0.0, -1.75, 0.0),
            ("Car2", 0.52, -95.390465, 64.592068, 5.067815),
            ("Car2", 0.53, 0.0, 201.75, std::f64::consts::PI),
            ("Car2", 0.61, 0.0, 201.75, std::f64::consts::PI),
        ],
    );
}

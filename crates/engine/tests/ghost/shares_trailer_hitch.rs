//! A FollowGhostController car that connects a trailer in the Init (fixture
//! `ghost_shares_trailer_hitch.xosc` on straight.xodr, head start 1.5 s). esmini 3.6.0's ghost is
//! a copy of the car made before the Init that keeps the very same TrailerHitch (Vehicle's copy
//! constructor copies the hitch only when a trailer hangs on it), so the trailer connected in
//! the Init is on the ghost's hitch too and ScenarioEngine::step pulls it behind the ghost,
//! last: the trailer runs 4.45 m behind the ghost, at its speed, from the start of the head
//! start. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_shares_trailer_hitch.xosc";

#[test]
fn the_ghost_pulls_the_trailer_connected_to_its_entity() {
    let run = run_fixture_scenario(FIXTURE, 10.0);
    for (t, x, v) in [(-0.5, 107.55, 12.0), (0.5, 119.55, 12.0), (1.5, 139.47, 20.0), (5.5, 219.47, 20.0)] {
        let s = at(&run, "Trailer", t);
        assert!(close(s.x, x, 1e-3) && close(s.y, -1.75, 1e-3) && close(s.speed, v, 1e-3), "Trailer at {t} s: {s:?}, esmini x {x} speed {v}");
    }
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

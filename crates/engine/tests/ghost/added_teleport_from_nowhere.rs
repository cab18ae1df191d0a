//! A ghost its Init left nowhere comes back with its added teleport. The ghost's copy of an Init
//! teleport to a TrajectoryPosition leaves it at the origin, on no road
//! (`init_trajectory_position.rs`); an event on its entity during the head start makes esmini add
//! the ghost's teleport (ScenarioEngine::CreateGhostTeleport), and that teleport, started before
//! time 0, puts the ghost on its entity's position (Position::TeleportTo), from where it moves.
//!
//! Fixture `ghost_added_teleport_from_nowhere.xosc` on tee_lht.xodr, reduced from a generated
//! scenario. Numbers from esmini 3.6.0's run; before the fix the ghost stood at the origin and
//! Car1 was 207 m off at the end.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_added_teleport_from_nowhere.xosc";

#[test]
fn the_added_teleport_puts_a_ghost_left_nowhere_back_on_the_road() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    // (entity, time, x, y, speed) from esmini's log
    let rows = [
        ("Car1_ghost", -2.0, -2.077293, -43.263031, 11.571684),
        ("Car1_ghost", 0.0, -2.609514, -15.664748, 16.1413),
        ("Car1_ghost", 3.0, -55.187626, -2.077293, 23.1313),
        ("Car1", 1.0, -2.077347, -42.184686, 12.12787),
        ("Car1", 3.0, -6.537595, -14.052188, 16.7937),
        ("Car1", 7.0, -89.051154, -2.088727, 25.759164),
    ];
    for (name, t, x, y, v) in rows {
        let e = at(&run, name, t);
        assert!(close(e.x, x, 1e-3) && close(e.y, y, 1e-3) && close(e.speed, v, 1e-3), "{name} t {t}: {e:?}, esmini ({x}, {y}) speed {v}");
    }
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

//! A ghost follower steps while its entity is away. esmini's ScenarioEngine::step steps every
//! active controller whether or not its entity is in the simulation (AddEntityAction and
//! DeleteEntityAction leave the controllers alone): the follower's vehicle drives on after the
//! Ego is deleted at 1 s, and when the Ego is added back at 2 s, 100 m on, the controller places
//! it where its vehicle drove in the same step.
//!
//! Fixture `follow_ghost_steps_while_away.xosc` on straight.xodr. Numbers from esmini 3.6.0's
//! run; before the fix the Ego came back at s = 200 and stayed 15 m ahead of esmini's.

use crate::common::oracle::run_fixture_scenario;
use crate::common::*;

#[test]
fn the_follower_comes_back_where_its_vehicle_drove_while_away() {
    let run = run_fixture_scenario("follow_ghost_steps_while_away.xosc", 10.0);
    // (time, x) from esmini's log: y stays -1.75 and the speed 15 m/s
    for (t, x) in [(1.0, 45.0), (2.02, 60.3), (3.0, 75.0), (5.0, 105.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, -1.75, 1e-3) && close(e.speed, 15.0, 1e-6), "t {t}: {e:?}, esmini x {x}");
    }
}

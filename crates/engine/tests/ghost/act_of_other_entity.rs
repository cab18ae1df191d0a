//! Which Acts a ghost's head start moves (ScenarioEngine::SetupGhost): an Act's start trigger
//! goes to the ghost's clock only when the ghost's entity is an actor of one of the Act's
//! maneuver groups. An Act of other entities starts when its SimulationTime condition holds
//! on the run's own clock, here at 0, not during the head start.
//!
//! Fixture `ghost_act_of_other_entity.xosc` on straight.xodr: the Ego follows its ghost (head
//! start 2 s); the Act, started by SimulationTime >= 0, teleports "Other" from s = 60 to
//! s = 100 as soon as it runs. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "ghost_act_of_other_entity.xosc";

#[test]
fn an_act_without_the_ghosts_entity_starts_on_the_runs_clock() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    let started = event_time(&run, "OtherAct", "start");
    assert!(started.is_some_and(|t| close(t, 0.0, 1e-9)), "OtherAct starts at {started:?}");
    // During the head start the Other car stands where the Init put it.
    assert_esmini_pose_at(&run, "Other", -1.0, 60.0, -5.25, 0.0);
    assert_esmini_pose_at(&run, "Other", 0.0, 60.0, -5.25, 0.0);
    assert_esmini_pose_at(&run, "Other", 0.01, 100.0, -5.25, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

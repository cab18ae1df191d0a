//! ReachPositionCondition with the triggering-entities rule `all`, as esmini 3.6 evaluates it
//! (TrigByReachPosition::CheckCondition): the result is only ever set to true in the loop over
//! the entities, so once the first listed entity is at the position the condition holds,
//! whatever the others do; listed after an entity that is not there, it never holds.
//!
//! Fixture `reach_position_all_entities.xosc` on straight.xodr: "Mover" passes s = 50 at 4 s,
//! "Parked" is 250 m away; the event listing Mover first fires (at 3.7 s, within the 3 m
//! tolerance), the one listing Parked first does not. Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn reach_position_with_rule_all_holds_once_the_first_listed_entity_is_there() {
    let run = run_fixture_scenario("reach_position_all_entities.xosc", 20.0);
    let fired = event_time(&run, "MoverFirstListed", "start");
    assert!(fired.is_some_and(|t| close(t, 3.7, 1e-9)), "MoverFirstListed starts at {fired:?}");
    assert_eq!(event_time(&run, "ParkedFirstListed", "start"), None);
    assert!(close(at(&run, "MoverFirst", 7.0).x, 78.0, 1e-9) && close(at(&run, "ParkedFirst", 7.0).x, 75.0, 1e-9));
    assert_matches_esmini("reach_position_all_entities.xosc", &run, 1e-3);
}

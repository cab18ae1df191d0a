//! StandStillCondition and OffroadCondition keep the current duration of the last entity
//! standing (off the road) for the entities checked after it (esmini's TrigByStandStill and
//! TrigByOffRoad): under the rule `all` a moving entity after one that has stood long enough
//! meets the condition too (fixture `duration_held_for_next_entity.xosc`; esmini 3.6.0 starts
//! StandingFirst at 1.01 s and OffroadFirst at 1.51 s, never MovingFirst or OnroadFirst).

use crate::common::*;

#[test]
fn a_duration_carries_over_to_the_next_triggering_entity() {
    let run = run_straight_fixture("duration_held_for_next_entity.xosc", 3.0);
    assert_eq!(event_time(&run, "StandingFirst", "start"), Some(1.01));
    assert_eq!(event_time(&run, "OffroadFirst", "start"), Some(1.51));
    assert_eq!(event_time(&run, "MovingFirst", "start"), None);
    assert_eq!(event_time(&run, "OnroadFirst", "start"), None);
}

//! esmini 3.6.0 reads only five value conditions (SimulationTime, Parameter, Variable,
//! StoryboardElementState, TrafficSignal); any other — TrafficSignalControllerCondition,
//! TimeOfDayCondition, UserDefinedValueCondition — is logged "not supported yet. Ignoring." by
//! ScenarioReader::parseOSCCondition and left out of its group by parseTrigger. The group is then
//! the AND of the remaining conditions, and a group left empty never holds
//! (ConditionGroup::Evaluate). Fixture `value_conditions_esmini_ignores.xosc` on `straight.xodr`:
//! "PhaseAlone" waits only for a controller phase, "PhaseAndTime" for a phase and t >= 1 s,
//! "TimeOfDayAndTime" for t >= 2 s and a time of day, "UserValueOrTime" for a user-defined
//! value or (t >= 4 s, delay 0.5 s). esmini 3.6.0 on the fixture starts them at never, 1.00 s,
//! 2.00 s and 4.50 s.

use crate::common::*;

#[test]
fn value_conditions_esmini_does_not_read_are_left_out_of_their_groups() {
    let run = run_fixture("value_conditions_esmini_ignores.xosc", "straight.xodr");
    let start = |name: &str| run.trace.events.iter().find(|ev| ev.element == name && ev.to == "running").map(|ev| ev.time);
    assert_eq!(start("PhaseAlone"), None);
    assert!(start("PhaseAndTime").is_some_and(|t| close(t, 1.0, 1e-9)), "{:?}", start("PhaseAndTime"));
    assert!(start("TimeOfDayAndTime").is_some_and(|t| close(t, 2.0, 1e-9)), "{:?}", start("TimeOfDayAndTime"));
    assert!(start("UserValueOrTime").is_some_and(|t| close(t, 4.5, 1e-9)), "{:?}", start("UserValueOrTime"));
    // One warning per condition left out, each naming the element.
    let named = |what: &str| run.warnings.iter().filter(|w| w.message.contains(&format!("{what} is left out"))).count();
    assert_eq!(named("TrafficSignalControllerCondition"), 2, "{:?}", run.warnings);
    assert_eq!(named("TimeOfDayCondition"), 1, "{:?}", run.warnings);
    assert_eq!(named("UserDefinedValueCondition"), 1, "{:?}", run.warnings);
}

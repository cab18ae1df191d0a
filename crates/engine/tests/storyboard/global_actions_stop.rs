//! Global actions finish by a stop transition in esmini: the Step of its ParameterSetAction,
//! VariableSet/Add/MultiplyByAction, EnvironmentAction, TrafficSignalStateAction,
//! AddEntityAction and DeleteEntityAction calls OSCAction::Stop (OSCGlobalAction.cpp), so the
//! action goes running → stopTransition → complete. A StoryboardElementStateCondition on the
//! action's endTransition never holds, one on its stopTransition does, and its event still
//! ends with an endTransition. Found by crates/difftest (s56056_00984: an event waiting for a
//! ParameterSetAction's end never starts in esmini).
//!
//! Fixture `global_actions_stop.xosc` on straight.xodr: Car at 10 m/s; a ParameterSetAction at
//! 1 s (OnParameterStop sets 15 m/s in the next step; OnParameterEnd, 30 m/s, never starts) and
//! a VariableSetAction at 2 s whose event's end sets 5 m/s. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_global_action_stops_rather_than_ends() {
    let run = assert_fixture_matches_esmini(
        "global_actions_stop.xosc",
        4.0,
        &[("Car", 1.5, 67.4, -1.75, 0.0), ("Car", 3.0, 80.1, -1.75, 0.0), ("Car", 4.0, 85.1, -1.75, 0.0)],
    );
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
}

//! ParameterAction with a ModifyAction, against esmini 3.6.0's own run of
//! `fixtures/parameter_modify_ignored.xosc` (straight road; `esmini-3.6.0 --fixed_timestep
//! 0.01`). esmini 3.6.0 reads only a ParameterAction's SetAction ("ParameterAction ModifyAction
//! not supported yet", ScenarioReader::parseOSCGlobalAction): P0 = 1 stays 1 after its
//! MultiplyByValue 5 (1 s) and AddValue 7 (1.5 s) events complete, so the SpeedAction waiting
//! for P0 > 3 never starts and the car keeps 10 m/s (x = 40 at 3 s in esmini's log).

use crate::common::*;

#[test]
fn a_parameter_modify_action_leaves_the_parameter_as_esmini_does() {
    let run = run_straight_fixture("parameter_modify_ignored.xosc", 3.0);
    assert_esmini_x_speed(&run, &[("Car", 1.5, 25.0, 10.0), ("Car", 3.0, 40.0, 10.0)], 1e-9);
    assert_eq!(event_time(&run, "ESpeed", "start"), None);
    assert!(event_time(&run, "EModify", "end").is_some_and(|t| close(t, 1.01, 1e-9)));
    assert_eq!(run.warnings.len(), 2, "{:?}", run.warnings);
}

//! A maneuver group that runs again resets its events' triggers, so a condition delay counts
//! again from the new execution (esmini's StoryBoardElement::End → child Reset → Trigger::Reset).

use crate::common::*;

#[test]
fn a_repeated_group_waits_for_the_condition_delay_again() {
    // The event's condition (t > 0) is true from the start; its 1 s delay makes the event start
    // at 1.01 (the first evaluation after t = 0 that has the value 1 s in the past). The step
    // speed action ends at once, the maneuver and its group end, the group goes to standby and
    // restarts in the next frame; with the trigger reset the delay runs again from there.
    let init = format!("{}{}", teleport("Ego", 10.0, -1), teleport("Target", 50.0, -1));
    let ev = event("E", "overwrite", &speed_action("step", "time", 0.0, 5.0), &trigger(&sim_time(0.0, "greaterThan", "none", 1.0)));
    let stories = story("Ego", &ev).replace(r#"maximumExecutionCount="1" name="G""#, r#"maximumExecutionCount="2" name="G""#);
    let stop = stop_at(5.0);
    let text = xosc(&init, &stories, &stop);
    let run = run(&text);
    let starts: Vec<f64> = run.trace.events.iter().filter(|e| e.element == "E" && e.transition == "start").map(|e| e.time).collect();
    // Also what esmini 3.6.0 logs for this scenario (run by hand): E starts at 1.010 and,
    // after G restarts at 1.020, at 2.020.
    assert_eq!(starts.len(), 2, "{starts:?}");
    assert!(close(starts[0], 1.01, 1e-9) && close(starts[1], 2.02, 1e-9), "{starts:?}");
    assert!(close(event_time(&run, "G", "start").unwrap_or(0.0), 0.0, 1e-9));
}

#[test]
fn a_reset_forgets_the_state_changes_seen_so_far() {
    // Fixture `state_changes_forgotten_on_reset.xosc`: a repeatable event started by its own
    // running state. esmini 3.6.0 runs it once, at 1.00 s: ending back in standby resets its
    // start trigger, and TrigByState::Reset drops the start registered before.
    let run = run_straight_fixture("state_changes_forgotten_on_reset.xosc", 2.0);
    let starts: Vec<f64> = run.trace.events.iter().filter(|e| e.element == "Repeat" && e.transition == "start").map(|e| e.time).collect();
    assert_eq!(starts, vec![1.0]);
}

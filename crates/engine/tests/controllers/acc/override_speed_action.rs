//! A SpeedAction ends in its start while a controller in override mode drives the entity's
//! speed (esmini's LongSpeedAction::Start: `IsControllerModeOnDomains(MODE_OVERRIDE,
//! DOMAIN_MASK_LONG)` → `OSCAction::End`), and, ended during the trigger pass, it is complete
//! for the triggers after it in the same step. Fixture `acc_override_speed_action.xosc`
//! (straight road): Ego's ACC in override mode keeps 20 m/s; a SpeedAction to 25 m/s at
//! t > 1; Target, parked at s = 500, is teleported to s = 800 when that action completes.
//! Expected values: esmini 3.6.0 on the same fixture (`esmini_run_one.py … --max_time 6`).

use crate::common::*;

#[test]
fn a_speed_action_ends_at_once_under_an_overriding_acc() {
    let run = run_straight_fixture("acc_override_speed_action.xosc", 6.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini's log at 1.01 s: Faster starts and completes, then Hop starts in the same step;
    // Target is at s = 800 from the 1.02 s row, Ego keeps 20 m/s (x 110 at 5 s).
    assert!(close(at(&run, "Target", 1.01).x, 500.0, 1e-9));
    assert!(close(at(&run, "Target", 1.02).x, 800.0, 1e-9));
    let e = at(&run, "Ego", 5.0);
    assert!(close(e.speed, 20.0, 1e-12) && close(e.x, 110.0, 1e-9), "{e:?}");
    let faster_ends = run.trace.events.iter().find(|ev| ev.element == "Faster" && ev.to == "complete");
    assert!(faster_ends.is_some_and(|ev| close(ev.time, 1.01, 1e-9)), "{faster_ends:?}");
}

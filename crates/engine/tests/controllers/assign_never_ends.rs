//! Controller actions that never end. An AssignControllerAction runs until the stop: esmini's
//! AssignControllerAction::Start assigns (and activates) the controller without ending the
//! action, and its Step is empty.
//! Fixture `assign_controller_never_ends.xosc` on straight.xodr: a lane change waiting for the
//! action's endTransition never starts. esmini 3.6.0 logs "A1 initState -> startTransition ->
//! runningState" at 1.01 s and "A1 runningState -> stopTransition -> completeState" at the stop
//! (5.01 s), and keeps Ego in lane −1 (y −1.75) at 20 m/s; before the fix the lane change ran.

use crate::common::*;

#[test]
fn the_action_runs_on_and_what_waits_for_its_end_never_starts() {
    let run = run_fixture("assign_controller_never_ends.xosc", "straight.xodr");
    for (t, x) in [(1.0, 40.0), (2.0, 60.0), (3.0, 80.0), (5.0, 120.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-6) && close(e.y, -1.75, 1e-9) && close(e.speed, 20.0, 1e-9), "t {t}: {e:?}, esmini x {x}");
    }
}

#[test]
fn an_activation_naming_no_controller_of_the_entity_never_ends_either() {
    // activate_unknown_controller_never_ends.xosc: ActivateControllerAction::Start finds no
    // controller named `Nobody`, so it neither starts nor ends the action; esmini 3.6.0 keeps
    // Ego in lane −1 at 20 m/s (the ACC, set speed 30, stays off).
    let run = run_fixture("activate_unknown_controller_never_ends.xosc", "straight.xodr");
    for (t, x) in [(1.0, 40.0), (3.0, 80.0), (5.0, 120.0)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-6) && close(e.y, -1.75, 1e-9) && close(e.speed, 20.0, 1e-9), "t {t}: {e:?}, esmini x {x}");
    }
}

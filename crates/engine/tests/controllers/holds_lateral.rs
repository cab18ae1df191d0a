//! A controller in override mode that holds the lateral domain makes a lane change do nothing
//! and never end (esmini's LatLaneChangeAction::Start and ::Step: `IsControllerModeOnDomains(
//! MODE_OVERRIDE, DOMAIN_MASK_LAT)` → return): here an ALKS_R157SM controller activated on both
//! domains. Fixture `controller_holds_lateral.xosc` (straight road): Alks (the controller) and
//! Plain (none), both at 10 m/s in lane -1, each asked at t > 1 to change to lane -2 in 2 s.
//! Expected values: esmini 3.6.0 on the same fixture (Alks keeps its lane, its lane change runs
//! to the end of the run; Plain's ends at 3 s).

use crate::common::*;

#[test]
fn a_lane_change_idles_while_a_controller_holds_the_lateral_domain() {
    let run = run_fixture("controller_holds_lateral.xosc", "straight.xodr");
    let (a, p) = (at(&run, "Alks", 5.0), at(&run, "Plain", 5.0));
    assert!(close(a.x, 150.0, 1e-6) && close(a.y, -1.75, 1e-9), "{a:?}");
    assert!(close(p.x, 349.617, 2e-3) && close(p.y, -5.25, 1e-6), "{p:?}");
    let end = |name: &str| run.trace.events.iter().find(|ev| ev.element == name && ev.to == "complete").map(|ev| (ev.time, ev.transition.clone()));
    assert!(end("ToRightPlain").is_some_and(|(t, _)| close(t, 3.0, 1e-9)), "{:?}", end("ToRightPlain"));
    assert!(end("ToRightAlks").is_some_and(|(t, tr)| close(t, 5.01, 1e-9) && tr == "stop"), "{:?}", end("ToRightAlks"));
}

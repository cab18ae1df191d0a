//! An AssignControllerAction never ends by itself (esmini's AssignControllerAction::Step does
//! nothing and no rule ends it): its event stays running, and what waits for its end waits for
//! ever. Found by crates/difftest (r10 s27027_00916, r11 wa-base s27027_00916). Fixture
//! `alks_assigned_never_ends.xosc` (straight road): at 1 s Car is assigned an ALKS R157
//! controller, activated; Witness's SpeedAction to 20 m/s waits for the assignment's end
//! transition. Expected: esmini 3.6.0 on the same fixture (Witness keeps 10 m/s; esmini the same
//! whether the controller is an ACC or an ALKS R157 one, activated on both domains or one, in a
//! 1.1 or a 1.3 file; main ended the assignment at once and Witness sped up).

use crate::common::*;

#[test]
fn an_assign_controller_action_never_ends() {
    let run = run_fixture("alks_assigned_never_ends.xosc", "straight.xodr");
    assert!(event_time(&run, "AssignA", "start").is_some_and(|t| close(t, 1.01, 1e-9)), "{:?}", event_time(&run, "AssignA", "start"));
    assert!(event_time(&run, "AssignA", "end").is_none());
    assert_esmini_x_speed(&run, &[("Witness", 2.0, 70.0, 10.0), ("Witness", 3.0, 80.0, 10.0), ("Car", 3.0, 80.0, 10.0)], 1e-6);
}

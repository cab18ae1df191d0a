//! Whether an entity's motion is overridden: esmini's Object::IsControllerModeOnDomains walks
//! the entity's controllers in assignment order and answers with the mode of the first one
//! active on the domain, ignoring the rest. The engine asked whether any controller overrode.
//! Found by a helper on s65065_00904 (an additive ACC assigned before an ALKS R157 in
//! override mode, whose SpeedAction the engine ended).
//!
//! Fixture `first_active_controller_decides_override.xosc` on straight.xodr: ACC (additive)
//! assigned at 0.5 s, ALKS R157 (override) at 1 s, a SpeedAction to 20 m/s at 2 s. The ACC
//! decides, so the SpeedAction runs: 10.17 m/s at 3 s, x 60.35 at 4 s. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;
use crate::common::*;

#[test]
fn the_first_controller_active_on_a_domain_decides_whether_it_is_overridden() {
    let run = assert_fixture_matches_esmini("first_active_controller_decides_override.xosc", 5.0, &[("Ego", 4.0, 60.345419, -1.75, 0.0)]);
    assert!(close(at(&run, "Ego", 3.0).speed, 10.171825, 1e-5), "speed at 3 s: {}", at(&run, "Ego", 3.0).speed);
}

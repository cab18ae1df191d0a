//! Which entities a NaturalDriver counts as near: esmini's ControllerNaturalDriver::
//! FilterSurroundingVehicles asks ScenarioEngine::GetDistance, which measures a pair again only
//! when it is due (or either entity was teleported this step). A pair found more than twice
//! the look-ahead ahead is due again after 3 s, and until then the other car is not near,
//! however close it comes. Found by a helper on s65065_00139 (a driver changing lanes 0.6 s
//! early).
//!
//! Fixture `natural_driver_far_lead_held_three_seconds.xosc` on straight.xodr: the driver
//! (look-ahead 30 m, 15 m/s) starts 65 m behind a parked car. The car is within 30 m from
//! 2.35 s, but the driver first sees it at the 3.01 s step (it slows to 14.97 m/s there) and
//! changes lanes after. esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_lead_first_measured_beyond_twice_the_look_ahead_is_unseen_for_three_seconds() {
    assert_fixture_matches_esmini(
        "natural_driver_far_lead_held_three_seconds.xosc",
        5.0,
        &[("Ego", 3.0, 65.0, -1.75, 0.0), ("Ego", 3.02, 65.2994, -1.75, 0.0), ("Ego", 4.0, 79.939123, -2.593453, 6.178955)],
    );
}

//! A NaturalDriver moves its entity with Object::MoveAlongS (ControllerNaturalDriver::Step), the
//! default controller's own move: without a route, a junction whose arms turn alike is left
//! by a draw from esmini's generator, not by the first arm.
//!
//! Fixture `natural_driver_junction_draw.xosc` on tee_lht.xodr (the difftest generator's
//! left-hand-traffic T): the car drives up the stem (road 3) alone at 15 m/s and takes the
//! left arm by the draw (seed 0). Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

const FIXTURE: &str = "natural_driver_junction_draw.xosc";

#[test]
fn a_natural_driver_draws_the_arm_of_a_junction_whose_arms_turn_alike() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    assert_esmini_pose_at(&run, "Ego", 8.0, -1.75, -20.0, 1.570795);
    assert_esmini_pose_at(&run, "Ego", 9.0, -7.575076, -6.632735, 2.392713);
    assert_esmini_pose_at(&run, "Ego", 12.0, -51.345717, -1.75, std::f64::consts::PI);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

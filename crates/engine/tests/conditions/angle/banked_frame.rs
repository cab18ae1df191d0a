//! An AngleCondition in the road or lane frame measures the heading from the reference line's
//! heading (esmini's TrigByAngle: GetH − GetHRoad, or GetHRoadInDrivingDirection; Track2XYZ
//! sets h_road_ from the geometry alone). On a banked road whose roll changes, the entity's own
//! heading turns off the reference line (EvaluateHPR composes GetPOffset's pitch with the
//! roll), and that turn is what the condition sees.
//!
//! Fixture `angle_condition_banked.xosc` on `banked.xodr` (roll 0.01·s): Ego on lane −1 (lane
//! frame, 0.01 ± 0.005 rad) and Outer on lane −2 (road frame, 0.02 ± 0.005 rad) speed up to
//! 20 m/s once their heading has turned that far, both at 1.9 s. Before, the engine measured
//! from a frame turned with the entity, so neither ever sped up. Found by crates/difftest
//! (s32032_00747 on pitch_by_super_elevation.xodr: a lane change 15.6 m off). Expected
//! values: esmini 3.6.0 on the fixture.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn an_angle_condition_on_a_banked_road_measures_from_the_reference_line() {
    assert_fixture_matches_esmini(
        "angle_condition_banked.xosc",
        6.0,
        &[("Ego", 1.91, 29.2, -1.675923, 0.005038), ("Ego", 2.0, 31.0, -1.666584, 0.005339), ("Outer", 2.0, 31.0, -4.999751, 0.016015)],
    );
}

//! esmini's NURBS position: NurbsShape::EvaluateInternal divides by the weight summed over every
//! basis value, but adds a control point to the position only where its basis value is above
//! SMALL_NUMBER (1e-6). Just after a knot (and at the start) the point is pulled towards the
//! origin by about 1e-6 of its coordinates: half a millimetre at x 850. Found by a helper on
//! s70070_00292, where that half millimetre is an acceleration an AccelerationCondition reads.
//!
//! Fixture `nurbs_small_basis_values_left_out.xosc` on difftest_curve.xodr: the car is at
//! x 851.879882 at 0.01 s (exact evaluation 851.8800), and E1 (an AccelerationCondition) starts
//! at 0.52 s; with the exact sum it never started. esmini 3.6.0's numbers.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn a_nurbs_point_leaves_out_control_points_of_tiny_basis_value() {
    let run = run_fixture_scenario("nurbs_small_basis_values_left_out.xosc", 12.82);
    assert!(close(at(&run, "Car0", 0.01).x, 851.879882, 2e-6), "x at 0.01 s: {}", at(&run, "Car0", 0.01).x);
    let t = event_time(&run, "E1", "start");
    assert!(t.is_some_and(|t| close(t, 0.52, 1e-9)), "E1 starts at {t:?}");
    assert_matches_esmini("nurbs_small_basis_values_left_out.xosc", &run, 1e-3);
}

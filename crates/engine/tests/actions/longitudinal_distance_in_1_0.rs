//! A LongitudinalDistanceAction in an OpenSCENARIO 1.0 file (fixture
//! `long_distance_in_1_0.xosc`, straight road, everyone at 10 m/s): 1.0 has no displacement,
//! so esmini ignores the attribute and keeps the distance's sign (ScenarioReader reads the
//! displacement from 1.1 on; LongDistanceAction::Step with displacement NONE). Ego, told 10 m
//! from Lead with displacement="leadingReferencedEntity", ends 10 m behind it; Side, told -8 m
//! from Lead2, ends 8 m ahead. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn a_1_0_longitudinal_distance_keeps_its_sign_and_ignores_the_displacement() {
    let run = run_fixture("long_distance_in_1_0.xosc", "straight.xodr");
    for (name, x) in [("Ego", 119.4), ("Lead", 129.4), ("Side", 137.4), ("Lead2", 129.4)] {
        let e = at(&run, name, 2.94);
        assert!(close(e.x, x, 1e-4), "{name}: {e:?}, esmini x {x}");
    }
}

//! An Orientation without a `type` (fixtures `orientation_untyped_1_2.xosc` and its 1.3 twin,
//! straight road along +x): esmini's ScenarioReader::parseOSCOrientation reads it as absolute
//! up to OpenSCENARIO 1.2 and as relative from 1.3. Ego on lane 1 (against s) with h 0.3,
//! Lead on a RoadPosition with h 3.1416, Side 20 m behind Lead in Lead's frame with h 0.2.
//! Expected values: esmini 3.6.0 on the fixtures, at 2.94 s.

use crate::common::*;

/// The file's h for Lead, 3.1416 as written (not π).
const WRITTEN_HALF_TURN: f64 = 31416.0 / 10000.0;

fn check(run: &engine::Run, rows: &[(&str, f64, f64, f64)]) {
    for &(name, x, h, speed) in rows {
        let e = at(run, name, 2.94);
        assert!(close(e.x, x, 1e-4) && close(e.h, h, 1e-4) && close(e.speed, speed, 1e-6), "{name}: {e:?}, esmini x {x} h {h}");
    }
}

#[test]
fn an_untyped_orientation_is_absolute_before_1_3() {
    let run = run_fixture("orientation_untyped_1_2.xosc", "straight.xodr");
    // Ego faces 0.3 and drives along s on lane 1; Side faces 0.2 whatever Lead's heading
    check(&run, &[("Ego", 179.4, 0.3, 10.0), ("Lead", 26.48, WRITTEN_HALF_TURN, 8.0), ("Side", 84.7, 0.2, 5.0)]);
}

#[test]
fn an_untyped_orientation_is_relative_from_1_3() {
    let run = run_fixture("orientation_untyped_1_3.xosc", "straight.xodr");
    check(&run, &[("Ego", 120.6, 3.441593, 10.0), ("Lead", 26.48, WRITTEN_HALF_TURN, 8.0), ("Side", 55.3, 3.3416, 5.0)]);
}

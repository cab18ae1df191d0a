//! A scenario's `roadId` read as esmini reads it (ScenarioReader's ResolveRoadIdFromStr, with
//! the internal ids of OpenDrive::EstablishUniqueIds): `std::stod` takes the leading number, so
//! "3B" and "3.0" both name road 3 (even though a road "3B" exists), while "Kalle", with no
//! leading number, is looked up by name. Found by crates/difftest (m303/s303_00230, a route
//! waypoint on road "2Kalle3" of fabriksgatan_mixed_id_types.xodr, which esmini puts on road
//! 2). Fixture `road_id_leading_number.xosc` on `mixed_ids.xodr` (roads "Kalle" at y = 0, "3" at
//! y = 100, "3B" at y = 200, all along +x); expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 2] = [(0.0, 20.0, 98.25, 10.0), (2.0, 40.0, 98.25, 10.0)];
const AHEAD: [(f64, f64, f64, f64); 2] = [(0.0, 50.0, -1.75, 5.0), (2.0, 60.0, -1.75, 5.0)];
const THIRD: [(f64, f64, f64, f64); 2] = [(0.0, 80.0, 98.25, 5.0), (2.0, 90.0, 98.25, 5.0)];

#[test]
fn a_road_id_with_a_leading_number_names_the_road_of_that_number() {
    let run = run_fixture_on("road_id_leading_number.xosc", "mixed_ids.xodr", 2.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-6);
    assert_esmini_rows(&run, "Ahead", &AHEAD, 1e-6);
    assert_esmini_rows(&run, "Third", &THIRD, 1e-6);
}

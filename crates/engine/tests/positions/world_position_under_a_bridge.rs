//! A point in the world that lies both on a bridge and on the road beneath it is attached to
//! the road at the height it is asked at: esmini's Position::XYZ2TrackPos adds to a road's
//! distance the height difference from its reference line where that exceeds 2 m. A
//! WorldPosition without z, and a RelativeObjectPosition without dz (whatever the height of
//! its reference entity), ask at z = 0; a WorldPosition with z asks there. Found by
//! crates/difftest (s35035_00370, s25025_00692 on SampleDatabase.xodr: the road first in the
//! file, 9 m up, had been taken). Fixture `world_position_under_a_bridge.xosc` on
//! `bridge.xodr`: road 1 along +x at z = 8 (first in the file) crosses road 2 along +y at
//! z = 0; Below (no z, facing +y) and Beside (1 m from Above, turned to +y) take road 2,
//! Above (z = 8, facing +x) road 1. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const BELOW: [(f64, f64, f64, f64); 3] = [(0.0, 101.75, -1.0, 10.0), (1.0, 101.75, 9.0, 10.0), (2.0, 101.75, 19.0, 10.0)];
const ABOVE: [(f64, f64, f64, f64); 3] = [(0.0, 101.75, -1.0, 10.0), (1.0, 111.75, -1.0, 10.0), (2.0, 121.75, -1.0, 10.0)];
const BESIDE: [(f64, f64, f64, f64); 3] = [(0.0, 100.75, -1.0, 10.0), (1.0, 100.75, 9.0, 10.0), (2.0, 100.75, 19.0, 10.0)];

#[test]
fn a_point_under_a_bridge_takes_the_road_at_the_asked_height() {
    let run = run_fixture_on("world_position_under_a_bridge.xosc", "bridge.xodr", 2.0);
    assert_esmini_rows(&run, "Below", &BELOW, 1e-6);
    assert_esmini_rows(&run, "Above", &ABOVE, 1e-6);
    assert_esmini_rows(&run, "Beside", &BESIDE, 1e-6);
    // esmini's z: the road each is on.
    for (name, z) in [("Below", 0.0), ("Above", 8.0), ("Beside", 0.0)] {
        let e = at(&run, name, 1.0);
        assert!(close(e.z, z, 1e-6), "{name}: {e:?}");
    }
}

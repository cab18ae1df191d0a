//! A WorldPosition without z on a road that climbs and falls again is placed on the segment
//! esmini's Position::XYZ2TrackPos weighs nearest, not at the exact projection: asked at z = 0,
//! each OSI segment of lane 0 gets |0 − its z| added when that exceeds 2 m, and 3 m when the
//! point lies outside the segment, so a point high on the climb takes the descending half
//! (whose end lies at z = 0), and its s is then measured from that half's first OSI point
//! (s = 49.875, just short of the crest where the slope changes) by the unsigned distance: the
//! point is mirrored about it. A point low on the climb (z 10 there, the descent 30 m away)
//! stays where it projects. Found by crates/difftest (s33033_00852, s31031_00622 on
//! slope_up_slope_down.xodr). Fixture `world_position_on_a_hill.xosc` on `hill.xodr` (straight
//! 100 m road rising at 0.5 to z = 25 at s = 50, then falling): Ego at x = 40 (s 59.75), Peak
//! at x = 49 (s 50.75), Low at x = 20 (s 20). Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 3] = [(0.0, 40.0, -1.75, 10.0), (1.0, 69.75, -1.75, 10.0), (2.0, 79.75, -1.75, 10.0)];
const PEAK: [(f64, f64, f64, f64); 2] = [(1.0, 55.75, 1.75, 5.0), (2.0, 60.75, 1.75, 5.0)];
const LOW: [(f64, f64, f64, f64); 2] = [(1.0, 25.0, -1.75, 5.0), (2.0, 30.0, -1.75, 5.0)];

#[test]
fn a_world_point_high_on_a_climb_takes_the_descending_segment() {
    let run = run_fixture_on("world_position_on_a_hill.xosc", "hill.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-6);
    assert_esmini_rows(&run, "Peak", &PEAK, 1e-6);
    assert_esmini_rows(&run, "Low", &LOW, 1e-6);
    // esmini's z at the start: the road's elevation at the s found (59.75, 50.75, 20).
    for (name, z) in [("Ego", 20.125), ("Peak", 24.625), ("Low", 10.0)] {
        let e = at(&run, name, 0.0);
        assert!(close(e.z, z, 1e-6), "{name}: {e:?}");
    }
}

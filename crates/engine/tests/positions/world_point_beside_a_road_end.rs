//! An off-road point beside the joint of two roads is attached to the road whose piece of
//! reference line it lies across, even where it lies nearer the other road's end: esmini's
//! Position::XYZ2TrackPos weighs each road by the point's distance beyond the road's width
//! from its nearest lane-0 OSI segment and adds 3 m where the point lies beyond the road's
//! ends (outside every segment's sector). Found by crates/difftest (s27027_00989 on
//! lane_offset_intersection.xodr: a RelativeWorldPosition 16 m off the road, 0.07 m nearer the
//! end of road 6 than the junction road it lies across). Fixture
//! `world_point_beside_a_road_end.xosc` on `narrowing.xodr`: road 1 (lanes 3.5 m) along +x
//! to x = 100, road 2 (lanes 3 m) on from there; Beside at (100.2, −15) is 11.5 m from road
//! 1's edge and 12 m from road 2's: on road 2, lane −1 at s = 0.2, offset −13.5, it drives
//! on along y = −15 (on road 1, at its end, it would stop there). Expected values: esmini
//! 3.6.0 on the fixture.

use crate::common::*;

const BESIDE: [(f64, f64, f64, f64); 3] = [(0.0, 100.2, -15.0, 10.0), (1.0, 110.2, -15.0, 10.0), (2.0, 120.2, -15.0, 10.0)];

#[test]
fn an_off_road_point_beside_a_road_end_takes_the_road_it_lies_across() {
    let run = run_fixture_on("world_point_beside_a_road_end.xosc", "narrowing.xodr", 2.0);
    assert_esmini_rows(&run, "Beside", &BESIDE, 1e-6);
    let Some(rp) = at(&run, "Beside", 0.0).road else { panic!("Beside has a road position") };
    assert!(rp.lane_id == -1 && close(rp.s, 0.2, 1e-6) && close(rp.lane_offset, -13.5, 1e-6), "{rp:?}");
}

//! A WorldPosition off every road takes the s esmini's Position::XYZ2TrackPos interpolates on
//! the nearest OSI segment of the road's lane 0 (a chord of the reference line), not the
//! exact projection onto the reference line; with t kept, the entity then moves along s from
//! there, so its x and y jump to the (s, t) point at the first step. Near a change of
//! curvature the two differ by metres. Found by crates/difftest on ref_point.xodr. Fixture
//! `world_point_off_road_in_a_bend.xosc` on `bend_r5.xodr` (40 m straight along +x, a 90°
//! arc of radius 5 m to the left, 40 m straight along +y; lanes ±1, 3 m): Ego at (40, −15.03)
//! (exact projection s 40, esmini s 38.242944), Ahead at (20, −15) (exact s 20, esmini
//! s 19.189590). Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 3] = [(0.5, 43.356129, -14.746830, 10.0), (1.0, 48.130385, -13.305675, 10.0), (2.0, 55.902177, -7.178739, 10.0)];
const AHEAD: [(f64, f64, f64, f64); 3] = [(0.5, 21.689590, -15.0, 5.0), (1.0, 24.189590, -15.0, 5.0), (2.0, 29.189590, -15.0, 5.0)];

#[test]
fn an_off_road_world_point_takes_the_s_of_its_osi_segment() {
    let run = run_fixture_on("world_point_off_road_in_a_bend.xosc", "bend_r5.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-4);
    assert_esmini_rows(&run, "Ahead", &AHEAD, 1e-4);
}

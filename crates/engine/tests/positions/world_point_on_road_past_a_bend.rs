//! A WorldPosition on the road takes the s esmini's Position::XYZ2TrackPos interpolates on the
//! lane-0 OSI segment it weighs nearest, as an off-road one does (`world_point_off_road`):
//! past a bend the segment runs from inside the arc onto the straight, its end headings
//! differ, and the s comes from the angle between its end normals, not the exact projection.
//! The heading given plays no part (esmini gives the same s for h = −π/2, 0, π/2, π). With t
//! kept, the entity jumps to the (s, t) point at the first step. Found by crates/difftest on
//! ref_point.xodr (s32032_00961). Fixture `world_point_on_road_past_a_bend.xosc` on
//! `bend_r5.xodr` (40 m along +x, a 90° arc of radius 5 m to the left, 40 m along +y; lanes
//! ±1, 3 m): Ego at (43.5, 19.396) facing −y (exact s 62.25, esmini s 62.195612), Ahead at
//! (46.5, 30) facing +y (exact s 72.853982, esmini s 72.870605). Expected values: esmini 3.6.0
//! on the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 3] = [(0.5, 43.5, 14.341630, 10.0), (1.0, 43.5, 9.341630, 10.0), (2.0, 39.838469, 1.5, 10.0)];
const AHEAD: [(f64, f64, f64, f64); 3] = [(0.5, 46.5, 32.516623, 5.0), (1.0, 46.5, 35.016623, 5.0), (2.0, 46.5, 40.016623, 5.0)];

#[test]
fn an_on_road_world_point_takes_the_s_of_its_osi_segment() {
    let run = run_fixture_on("world_point_on_road_past_a_bend.xosc", "bend_r5.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-4);
    assert_esmini_rows(&run, "Ahead", &AHEAD, 1e-4);
}

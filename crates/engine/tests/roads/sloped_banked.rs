//! A lane position on a road both rolled (superelevation) and sloped (elevation): esmini's
//! Position::Track2XYZ turns (0, t, 0) by the road's rotation, heading · pitch · roll
//! (CreateRotationMatrix3d), with the pitch −atan of the slope, so the point lies
//! t·sin(roll)·sin(pitch) along the heading from the reference line's point at s, besides
//! t·cos(roll) across it, and t·sin(roll)·cos(pitch) above it. Found by crates/difftest on
//! slope_up_leaning_right.xodr (s26026_00693: 0.116 m along x). Fixture
//! `lane_position_on_a_sloped_banked_road.xosc` on `sloped_banked.xodr` (200 m along +x,
//! slope 0.1, roll 0.4 rad; lanes 1, −1, −2 of 3.5 m): Ego on lane −1 at s 50 facing +s, Ahead
//! on lane 1 at s 120 (offset 0.5) facing −s. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 3] = [(0.0, 50.067810, -1.611857, 10.0), (1.0, 60.067810, -1.611857, 10.0), (2.0, 70.067810, -1.611857, 10.0)];
const AHEAD: [(f64, f64, f64, f64); 3] = [(0.0, 119.912816, 2.072387, 5.0), (1.0, 114.912816, 2.072387, 5.0), (2.0, 109.912816, 2.072387, 5.0)];

#[test]
fn a_lane_position_on_a_sloped_banked_road_is_turned_by_the_pitch_too() {
    let run = run_fixture_on("lane_position_on_a_sloped_banked_road.xosc", "sloped_banked.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-4);
    assert_esmini_rows(&run, "Ahead", &AHEAD, 1e-4);
    // esmini's z: the elevation plus t·sin(roll)·cos(pitch).
    assert!(close(at(&run, "Ego", 0.0).z, 4.321900, 1e-4) && close(at(&run, "Ahead", 0.0).z, 12.871843, 1e-4));
}

/// The way back: a WorldPosition at those points takes s 50 and 120 in esmini
/// (Position::XYZ2TrackPos moves the point back along the heading by that shift before it
/// projects it on the straight reference line), so the entities drive on exactly as above.
/// Fixture `world_position_on_a_sloped_banked_road.xosc`: the same scene placed by world
/// positions. Expected values: esmini 3.6.0 on the fixture.
#[test]
fn a_world_point_on_a_sloped_banked_road_takes_the_s_it_came_from() {
    let run = run_fixture_on("world_position_on_a_sloped_banked_road.xosc", "sloped_banked.xodr", 2.0);
    assert_esmini_rows(&run, "Ego", &EGO[1..], 1e-4);
    assert_esmini_rows(&run, "Ahead", &AHEAD[1..], 1e-4);
    assert!(close(at(&run, "Ego", 0.5).x, 55.067810, 1e-4) && close(at(&run, "Ahead", 0.5).x, 117.412816, 1e-4));
}

/// An entity moved by its world position (a polyline trajectory from x 40 to 55 along lane
/// −1's centre) is re-attached by XYZ2TrackPos from where it was, with the same shift taken
/// off: its s stays x − 0.067810, and when the trajectory ends at 1.5 s it drives on along the
/// lane without a jump. Fixture `trajectory_onto_a_sloped_banked_road.xosc`. Expected values:
/// esmini 3.6.0 on the fixture.
#[test]
fn an_entity_moved_by_its_world_position_keeps_its_place_on_a_sloped_banked_road() {
    let run = run_fixture_on("trajectory_onto_a_sloped_banked_road.xosc", "sloped_banked.xodr", 3.0);
    let rows = [(1.0, 50.0, -1.611857, 10.0), (2.0, 60.0, -1.611857, 10.0), (3.0, 70.0, -1.611857, 10.0)];
    assert_esmini_rows(&run, "Ego", &rows, 1e-4);
}

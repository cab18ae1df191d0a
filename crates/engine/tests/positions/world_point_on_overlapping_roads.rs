//! A point in the world that lies on several roads of a junction is attached to the road that
//! comes first in the network, not to the one whose lane centre is nearest: esmini's
//! Position::XYZ2TrackPos walks the roads in order and replaces a road the point lies on only
//! by one it is strictly nearer to. Found by crates/difftest (seed_9009/s9009_00129: a route's
//! WorldPosition waypoint). Fixture `world_point_on_overlapping_junction_roads.xosc` on
//! `crossing.xodr`: (4.863, 15.596) lies on connecting road 100 (from road 1 to road 2, lane
//! -2 with offset 1.01) and on road 107 (from road 3 to road 2, the centre of lane -2).
//! Placed, put there by a WorldPosition, drives along road 100 onto road 2 at t = -4.24; Ego's
//! route from road 3 towards the junction finds no way to road 100 (esmini's RoadPath), so its
//! RoutePosition is the route's first waypoint, pathS unused. Expected values: esmini 3.6.0 on
//! the fixture.

use crate::common::*;

const EGO: [(f64, f64, f64, f64); 2] = [(0.0, -136.03, -5.25, 10.0), (2.0, -116.03, -5.25, 10.0)];
const PLACED: [(f64, f64, f64, f64); 2] = [(1.0, 4.235356, 25.546442, 10.0), (2.0, 4.235356, 35.546442, 10.0)];

#[test]
fn a_point_on_two_junction_roads_takes_the_first_road() {
    let run = run_fixture_on("world_point_on_overlapping_junction_roads.xosc", "crossing.xodr", 2.0);
    assert_esmini_rows(&run, "Placed", &PLACED, 1e-3);
    assert_esmini_rows(&run, "Ego", &EGO, 1e-6);
    assert!(run.warnings.iter().any(|w| w.message.contains("no drivable way")), "{:?}", run.warnings);
}

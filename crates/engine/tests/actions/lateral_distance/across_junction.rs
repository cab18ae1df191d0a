//! LateralDistanceAction (road coordinates, rigid) between entities on two arms of a crossing
//! (`fixtures/crossing.xodr`, written by the difftest generator: four 300 m arms, roads 1–4,
//! around a junction whose connecting roads come in pairs laid the same way in opposite
//! directions). esmini's road path from the reference to the actor enters the junction only
//! through a connection whose incoming road is the reference's (RoadPath::Calculate), and
//! that connection's exit end decides whether the two face the same way (Position::Delta).
//! Expected values: esmini 3.6.0's log of `fixtures/lat_distance_across_junction.xosc`
//! (actions start at t > 0.5 s; the first step only records the position).
//! - Car0 stands on road 4 (south arm), lane 2, facing north at x = 5.25;
//! - Car1 stands on road 2 (north arm), lane 2, facing south, and keeps 1.66 m left of Car0:
//!   esmini puts it at x = 6.91 (Car0's t + 1.66 with the two facing opposite ways);
//! - Car2 drives north on road 2, lane −1, at 5 m/s, 2 m right of Car0 with freespace: x = 1.25.

use crate::common::*;

#[test]
fn the_path_through_the_junction_decides_the_side_as_esmini() {
    let run = run_fixture_on("lat_distance_across_junction.xosc", "crossing.xodr", 4.0);
    let w: Vec<_> = run.warnings.iter().filter(|w| w.message.contains("LateralDistanceAction")).collect();
    assert!(w.is_empty(), "{w:?}");
    // (entity, time, x, y) rows of esmini's log.
    for (name, t, x, y) in [
        ("Car1", 0.52, -5.25, 175.31),
        ("Car1", 0.53, 6.91, 175.31),
        ("Car1", 4.0, 6.91, 175.31),
        ("Car2", 0.52, 1.75, 142.6),
        ("Car2", 0.53, 1.25, 142.65),
        ("Car2", 2.0, 1.25, 150.0),
        ("Car2", 4.0, 1.25, 160.0),
    ] {
        let s = at(&run, name, t);
        assert!(close(s.x, x, 2e-6) && close(s.y, y, 2e-6), "{name} at {t}: ({}, {}) against esmini ({x}, {y})", s.x, s.y);
    }
}

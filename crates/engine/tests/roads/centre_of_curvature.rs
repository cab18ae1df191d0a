//! A lane near or past its bend's centre of curvature (esmini's Position::DistanceToDS): a
//! distance along the lane at lateral t is `1 / (1 − curvature·t)` of road s, unguarded, so a
//! lane close to the centre moves fast in s; at or past it (curvature·t above 1 − 1e-6) esmini
//! first locates the position afresh from its world point (XYZ2TrackPos, the s interpolated on
//! the OSI segment found), and where the factor is still infinite or negative the position
//! jumps to a road end. Found on difftest scenarios on ref_point.xodr (a pedestrian placed 5 m
//! left of a bend of radius 5 went 40 m off in esmini's first step, not in ours: ours clamped
//! the factor to 10). Fixture `moves_past_the_centre_of_a_bend.xosc` on `tight_bend.xodr`
//! (40 m straight, a left arc of radius 5, 40 m straight; lane 1 drives against s, a sidewalk
//! beyond it): Inside at t 4.7, Centre and Back at t 5 (Back reversing), Beyond at t 6. Beyond
//! is found on the straight at t 5.7, inside the sidewalk, and is attached to the driving lane
//! 1 (LaneSection::GetClosestLaneIdx): a lane offset of 4 at 0.5 s puts it at t 5.5, not 8.5.
//! Expected values: esmini 3.6.0 on the fixture (x, y).

use crate::common::*;

const ROWS: [(&str, f64, f64, f64); 15] = [
    ("Inside", 0.01, 40.107552, 4.719942),
    ("Inside", 0.1, 40.019985, 4.700666),
    ("Inside", 3.0, 36.963333, 4.7),
    ("Centre", 0.0, 40.0, 5.0),
    ("Centre", 0.01, 40.0, 45.0),
    ("Centre", 3.0, 40.0, 42.01),
    ("Beyond", 0.0, 39.282644, 5.696707),
    ("Beyond", 0.01, 39.970447, 5.696707),
    ("Beyond", 0.5, 38.990447, 5.696707),
    ("Beyond", 1.0, 37.990447, 5.5),
    ("Beyond", 3.0, 33.990447, 5.5),
    ("Back", 0.0, 40.0, 5.0),
    ("Back", 0.01, 0.0, 5.0),
    ("Back", 0.02, 0.01, 5.0),
    ("Back", 3.0, 2.99, 5.0),
];

#[test]
fn a_lane_at_or_past_the_centre_of_its_bend_moves_as_esmini_scales_it() {
    let run = run_fixture_on("moves_past_the_centre_of_a_bend.xosc", "tight_bend.xodr", 3.0);
    for (name, t, x, y) in ROWS {
        let e = at(&run, name, t);
        assert!(close(e.x, x, 1e-4) && close(e.y, y, 1e-4), "{name} at {t}: ({}, {}), esmini ({x}, {y})", e.x, e.y);
    }
}

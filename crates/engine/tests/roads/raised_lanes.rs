//! A lane's own height (`<lane><height>`: a kerb, a raised sidewalk): esmini's
//! Position::Track2XYZ turns the point (0, t, height) by the road's heading, pitch and roll, so
//! the height lifts a lane position along the road's tilted normal — up, and on a banked road
//! across too — the height read as Lane::GetHeightBySAndOffset does (records interpolated along
//! s, inner to outer across the lane). Found on esmini's traffic_lights.xosc: its pedestrians
//! on a sidewalk 0.12 m high were at z 0 in our run, at 0.12 in esmini's. Fixture
//! `positions_on_raised_lanes.xosc` on `raised_lanes.xodr` (200 m along +x, slope 0.1, roll
//! 0.2 rad; sidewalk 2 at 0.15 m, sidewalk −2 from 0.1 m inside to 0.2 m outside at s 0 and
//! 0.3 to 0.5 m at s 100): Ego on lane −2 (offset 0.5) from s 50 at 10 m/s, Ahead on lane 2
//! from s 120 facing −s at 5 m/s, OnKerb placed by a WorldPosition on lane −2 at 2 m/s.
//! Expected values: esmini 3.6.0 on the fixture (x, y, z).

use crate::common::*;

const ROWS: [(&str, f64, f64, f64, f64); 9] = [
    ("Ego", 0.0, 50.055912, -3.967450, 4.440877),
    ("Ego", 1.0, 60.053718, -3.971920, 5.462819),
    ("Ego", 6.0, 110.044941, -3.989801, 10.550587),
    ("Ahead", 0.0, 119.896414, 4.380499, 13.035856),
    ("Ahead", 1.0, 114.896414, 4.380499, 12.535856),
    ("Ahead", 6.0, 89.896414, 4.380499, 10.035856),
    ("OnKerb", 0.0, 30.0, -4.5, 2.083255),
    ("OnKerb", 1.0, 32.0, -4.5, 2.283255),
    ("OnKerb", 6.0, 42.0, -4.5, 3.283255),
];

#[test]
fn a_raised_lane_lifts_its_positions_along_the_roads_normal() {
    let run = run_fixture_on("positions_on_raised_lanes.xosc", "raised_lanes.xodr", 6.0);
    for (name, t, x, y, z) in ROWS {
        let e = at(&run, name, t);
        assert!(close(e.x, x, 1e-4) && close(e.y, y, 1e-4) && close(e.z, z, 1e-4), "{name} at {t}: {e:?}, esmini ({x}, {y}, {z})");
    }
}

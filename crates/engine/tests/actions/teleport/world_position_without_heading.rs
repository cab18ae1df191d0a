//! A WorldPosition without h faces its road's reference direction where it lies (the heading
//! relative to the road is 0, in whichever lane), and absolute 0 beyond the road's last OSI
//! point. The engine gave a teleport to such a position the absolute heading 0 anywhere. Found
//! by a helper on s75075_00549's trajectory family (the same rule as a trajectory vertex's).
//!
//! Fixture `teleport_world_no_heading.xosc` on crossing.xodr (the west arm runs along -x from
//! the centre): A and B are teleported mid-road into either lane and face π; C, at the arm's
//! far end, faces absolute 0 (logged 2π). esmini 3.6.0's numbers.

use crate::common::oracle::assert_fixture_matches_esmini;
use std::f64::consts::{PI, TAU};

#[test]
fn the_heading_is_the_roads_on_the_road_and_zero_past_its_end() {
    assert_fixture_matches_esmini(
        "teleport_world_no_heading.xosc",
        1.0,
        &[("A", 0.0, -250.0, 5.25, PI), ("B", 0.0, -250.0, -5.25, PI), ("C", 0.0, -320.0, -1.75, TAU)],
    );
}

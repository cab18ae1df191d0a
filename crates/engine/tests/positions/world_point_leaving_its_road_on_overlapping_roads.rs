//! A moving entity that leaves its road into the overlap of two other roads is attached to
//! the one first in the file unless the other is directly connected to its road: esmini's
//! Position::XYZ2TrackPos checks the current road, then every road in the file's order, and a
//! road that also contains the point replaces the best so far only when it is directly
//! connected to the current road (Road::IsDirectlyConnected: a road link, or a junction
//! connection with a lane link from the entity's lane). The engine took the road whose lane
//! centre was nearest. Found by a helper on s67067_00408 (a LoomingController's lane lock
//! through a junction).
//!
//! Fixtures on overlapping_roads.xodr (road 1 along y 0; roads 20 (left lanes, y 2 to 9) and 30
//! (right lanes, y 5 to 12) along +x, linked to nothing): a trajectory takes the car from road
//! 1 to (60, 7.75), inside both; a LaneOffsetAction to offset 0 at 6 s then drives to the
//! centre of the lane it was attached to. esmini 3.6.0's numbers:
//! - road 20 first in the file: lane 2, y 7.25 at 9 s (the engine: road 30's lane −2, y 6.75);
//! - the same scenario on `overlapping_roads_swapped.xodr` (road 30 first): y 6.75.

use crate::common::oracle::assert_fixture_matches_esmini;
use crate::common::*;

#[test]
fn the_first_road_in_the_file_is_kept() {
    let run = assert_fixture_matches_esmini("off_road_tie_first_in_file.xosc", 9.0, &[("Ego", 9.0, 99.6413, 7.25, 0.0)]);
    assert_eq!(at(&run, "Ego", 9.0).road.map(|r| r.lane_id), Some(2));
}

#[test]
fn with_the_other_road_first_that_one_is_kept() {
    let run = assert_fixture_matches_esmini("off_road_tie_first_in_file_swapped.xosc", 9.0, &[("Ego", 9.0, 99.6413, 6.75, 0.0)]);
    assert_eq!(at(&run, "Ego", 9.0).road.map(|r| r.lane_id), Some(-2));
}

//! LateralDistanceAction (road coordinates, rigid) across the crossing (`fixtures/crossing.xodr`)
//! when the reference drives *away* from the junction: esmini's road path from the reference
//! follows the reference's lane (RoadPath::CheckRoad keeps only roads its lane continues into,
//! Road::GetConnectingLaneId), and an outgoing lane enters the junction only through the
//! counter connections esmini adds for connecting roads that lead *to* the reference's road
//! (OpenDrive::CheckJunctionConnection). Such a connecting road is left by its start, so
//! Position::Delta counts the reference as coming in along the actor's road and the side turns
//! round against a path through a connection leaving the reference's road.
//! Expected values: esmini 3.6.0's log of `fixtures/lat_distance_lane_path.xosc` (the actions
//! start at 0.5 s; the first step only records the position):
//! - Car0 drives east on road 1, lane −1 (away from the junction); Car1 drives west on road 3,
//!   lane 1, and keeps 3 m left of Car0: esmini puts it at y = 1.25 (lane −1, offset 0.5);
//! - Car2 faces west on road 1, lane −1 (towards the junction, against its lane); Car3 drives
//!   west on road 3, lane −1, 3 m left of Car2: y = −4.75 (lane 2, offset −0.5).

use crate::common::*;
use std::f64::consts::PI;

#[test]
fn the_road_path_follows_the_reference_lane_as_esmini() {
    let run = run_fixture_on("lat_distance_lane_path.xosc", "crossing.xodr", 2.0);
    let w: Vec<_> = run.warnings.iter().filter(|w| w.message.contains("LateralDistanceAction")).collect();
    assert!(w.is_empty(), "{w:?}");
    // (entity, time, x, y, heading) rows of esmini's log: the jump's row faces along the jump.
    let rows = [
        ("Car1", 0.51, -125.1, -1.75, PI),
        ("Car1", 0.52, -125.2, 1.25, 1.604117),
        ("Car1", 2.0, -140.0, 1.25, PI),
        ("Car3", 0.51, -174.08, 1.75, PI),
        ("Car3", 0.52, -174.16, -4.75, 4.700082),
        ("Car3", 2.0, -186.0, -4.75, PI),
    ];
    assert_esmini_poses(&run, &rows, 2e-6, 1e-5);
}

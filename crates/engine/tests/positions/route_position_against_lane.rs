//! RoutePositions on routes that run against their lanes, and the entities placed relative to
//! them. esmini 3.6 (ScenarioReader's RoutePosition branch, OSCPositionRoute::SetRouteRefLaneCoord,
//! Position::SetRouteLanePosition, Route::SetPathS, Route::CalculcateWPDirWrtWP) faces a route
//! position from the road's reference direction — turned by π on a lane with a positive id when
//! no orientation is given, by the orientation's h (plus π on a lane driving against s) when one
//! is — never along the route's travel; it reads FromRoadCoordinates' t as an integer; a pathS
//! beyond the route leaves the position at the first waypoint; waypoints in a row on one road
//! are travelled in the order of their s. The numbers are esmini 3.6.0's runs of the fixtures
//! (`fixtures/route_position_against_lane.xosc` on `fork.xodr`,
//! `fixtures/route_position_across_opposite_roads.xosc` on `opposite_roads.xodr`); where esmini
//! runs here the whole runs are compared too.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use std::f64::consts::PI;

#[test]
fn positions_on_a_route_against_the_lanes_face_as_esmini_faces_them() {
    let run = run_fixture_scenario("route_position_against_lane.xosc", 2.0);
    // Route Back runs road 2 → 10 → 1 on lane 1 (against s). Lane 1 without an orientation
    // faces −s (π), lane −1 faces +s, wherever the route goes; the pedestrians 2 m ahead and 3 m
    // to the left of them land on the side the heading gives.
    assert_esmini_pose_at(&run, "Obst0", 0.0, 150.0, 1.75, PI);
    assert_esmini_pose_at(&run, "Ped0", 0.0, 148.0, -1.25, PI);
    assert_esmini_pose_at(&run, "Obst1", 0.0, 150.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ped1", 0.0, 152.0, 1.25, 0.0);
    assert_esmini_pose_at(&run, "Obst2", 0.0, 110.0, -1.35, 0.0);
    // With an orientation its h is relative, plus π on lane 1; "absolute" is read as relative.
    assert_esmini_pose_at(&run, "Obst3", 0.0, 90.0, 1.75, PI + 0.3);
    assert_esmini_pose_at(&run, "Ped3", 0.0, 87.685, 5.849, PI + 0.3);
    assert_esmini_pose_at(&run, "Obst4", 0.0, 90.0, -1.75, 0.3);
    assert_esmini_pose_at(&run, "Ped4", 0.0, 92.315, -5.849, 0.3);
    // FromRoadCoordinates: t = −2.6 is −2; the heading is the road's, turned by h.
    assert_esmini_pose_at(&run, "Obst5", 0.0, 125.0, -2.0, 0.0);
    assert_esmini_pose_at(&run, "Obst6", 0.0, 160.0, 2.0, 0.5);
    // Two waypoints on road 1 from s 80 to 20: pathS 30 is s 50; pathS 75 lies beyond the 60 m
    // route, so the position is the first waypoint.
    assert_esmini_pose_at(&run, "Obst7", 0.0, 50.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Obst8", 0.0, 50.0, 1.75, PI);
    assert_esmini_pose_at(&run, "Obst9", 0.0, 80.0, -1.75, 0.0);
    // Along the lanes through the junction's curve onto road 3: lane 1 still faces −s.
    assert_esmini_pose_at(&run, "Obst10", 0.0, 108.750, 3.984, 3.642);
    assert_esmini_pose_at(&run, "Obst11", 0.0, 114.826, 4.086, 3.892);
    let notes: Vec<&str> = run.warnings.iter().map(|w| w.message.as_str()).collect();
    assert!(notes.iter().any(|m| m.contains("t = -2.6 is read as -2")), "{notes:?}");
    assert!(notes.iter().any(|m| m.contains("pathS = 75 lies outside route `SameRoadBack`")), "{notes:?}");
    assert_matches_esmini("route_position_against_lane.xosc", &run, 1e-3);
}

#[test]
fn a_route_across_roads_of_opposite_direction_keeps_the_lane_id_as_written() {
    let run = run_fixture_scenario("route_position_across_opposite_roads.xosc", 2.0);
    // Route Across: lane −1 of road 0 (+x) continues in lane 1 of road 1 (whose s runs −x).
    // pathS 100 is road 1 at s 150 (x 250). Lane −1, as written, is road 1's lane −1 (y = +1.5)
    // facing road 1's +s (π, against the route); lane 1 lies at y = −1.5 facing 0, with or
    // without an orientation of h 0. FromRoadCoordinates t 1 at pathS 80 (road 1, s 170) is
    // y = −1, facing road 1's +s.
    assert_esmini_pose_at(&run, "Obst0", 0.0, 180.0, -1.5, 0.0);
    assert_esmini_pose_at(&run, "Obst1", 0.0, 250.0, 1.5, PI);
    assert_esmini_pose_at(&run, "Ped1", 0.0, 248.0, -1.5, PI);
    assert_esmini_pose_at(&run, "Obst2", 0.0, 250.0, -1.5, 0.0);
    assert_esmini_pose_at(&run, "Ped2", 0.0, 252.0, 1.5, 0.0);
    assert_esmini_pose_at(&run, "Obst3", 0.0, 250.0, -1.5, 0.0);
    assert_esmini_pose_at(&run, "Obst4", 0.0, 230.0, -1.0, PI);
    assert_matches_esmini("route_position_across_opposite_roads.xosc", &run, 1e-3);
}

//! RelativeRoadPosition and RelativeLanePosition measured across junctions and road links, as
//! esmini 3.6 resolves them (Position::EvaluateRelation): a copy of the reference entity's
//! position moves `ds` in road s through the network (Position::MoveAlongS, actualDistance
//! false) — the straightest arm, or the route's: the entity's own route first, else the
//! reference entity's — and the result keeps the reference entity's lane id plus dLane on the
//! road reached (a road position: the copy's t plus dt); the RoadPosition it becomes snaps to
//! the driving lane esmini's Track2Lane picks. Fixtures
//! `relative_positions_across_junctions.xosc` (fork.xodr) and
//! `relative_positions_across_opposite_roads.xosc` (opposite_roads.xodr); the numbers are
//! esmini 3.6.0's runs of them, and where esmini runs here the whole runs are compared too.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use std::f64::consts::PI;

#[test]
fn relative_positions_run_on_through_the_junction() {
    let run = run_fixture_scenario("relative_positions_across_junctions.xosc", 10.0);
    // Ego at road 1, s 90: 25 m ahead is 15 m into the straight arm's far road (road 2 at s 5).
    assert_esmini_pose_at(&run, "Ahead", 0.0, 115.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "AheadLane", 0.0, 115.0, -1.75, 0.0);
    assert_esmini_pose_at(&run, "AheadRoad", 0.0, 130.0, -0.75, 0.0);
    // dLane 1 from lane −1 is lane 1, on the road reached.
    assert_esmini_pose_at(&run, "AheadOtherLane", 0.0, 125.0, 2.05, 0.0);
    // Along the reference entity's route, or the placed entity's own: the curve to road 3.
    assert_esmini_pose_at(&run, "OnItsRoute", 0.0, 110.428, 0.913, 0.5);
    assert_esmini_pose_at(&run, "OwnRoute", 0.0, 118.302, 8.248, 1.0);
    // Behind the start of a road with nothing before it: its start.
    assert_esmini_pose_at(&run, "Behind", 0.0, 0.0, -1.75, 0.0);
    assert_matches_esmini("relative_positions_across_junctions.xosc", &run, 1e-3);
}

#[test]
fn relative_positions_across_opposite_roads_keep_the_reference_lane_id() {
    let run = run_fixture_scenario("relative_positions_across_opposite_roads.xosc", 10.0);
    // Road 0's lane −1 continues in road 1's lane 1, but the position takes lane −1 of road 1
    // (the reference's id): the other side, facing road 1's +s.
    assert_esmini_pose_at(&run, "Across", 0.0, 230.0, 1.5, PI);
    assert_esmini_pose_at(&run, "AcrossLane", 0.0, 230.0, 1.5, PI);
    // The copy follows lane −1 into road 1's lane 1 (t 1.5 there, y −1.5: road 1 runs −x);
    // its t plus dt 1 is 2.5, y −2.5, facing road 1's +s.
    assert_esmini_pose_at(&run, "AcrossRoad", 0.0, 230.0, -2.5, PI);
    assert_matches_esmini("relative_positions_across_opposite_roads.xosc", &run, 1e-3);
}

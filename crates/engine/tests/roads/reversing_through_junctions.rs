//! Cars reversing (negative speed) or driving against their lane into junctions, and cars put
//! beside the lanes by world positions, as esmini 3.6.0 moves them. The rules, from esmini's
//! source:
//! - Position::MoveToConnectingRoad measures each arm's turn from the heading of the lane's
//!   driving direction (GetHRoadInDrivingDirection), not from the way the car faces or moves;
//! - with a route it takes the arm towards the route road beyond the junction, found from the
//!   route's connecting road entered from this road whichever way the route runs
//!   (Route::GetRoadAtOtherEndOfIncomingRoad); a route that does not cross the junction from
//!   here gives the lane's first connection;
//! - the connections are the file's, then the counter connections esmini adds at load
//!   (OpenDrive::CheckJunctionConnection); a lane none starts from cannot enter the junction
//!   and stays at the road's end;
//! - a world position attaches to the nearest lane of the types esmini snaps to
//!   (LaneSection::GetClosestLaneIdx; a teleport's position snaps to driving lanes only), the
//!   heading relative to the lane leaving out the lane's drift atan(dt/ds)
//!   (Position::GetHOffset); a lane that narrows to nothing hands the entity to the lane of its
//!   snap types on the same side containing it, else the nearest (Position::MoveAlongS; a
//!   pedestrian's own types include sidewalks).
//!
//! Fixtures: `reversing_through_junctions.xosc` (fork.xodr), `junction_arms_one_way.xosc` (a T
//! junction whose file lists connections one way only, `t_junction_one_way.xodr`) and
//! `parking_bay_world_positions.xosc` (`bay.xodr`: a lane that ends on a curve beside a border
//! and a sidewalk). The numbers are esmini 3.6.0's runs of them; where esmini runs here the
//! whole runs are compared too.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};

#[test]
fn reversing_cars_take_the_arms_esmini_takes() {
    let run = run_fixture_scenario("reversing_through_junctions.xosc", 20.0);
    // Road 2's lane −1 has no connection into the junction: stuck at the road's start.
    assert_esmini_pose_at(&run, "NoConnection", 12.0, 120.0, -1.75, 0.0);
    // Lane 1 of road 2 connects back through road 10 to road 1.
    assert_esmini_pose_at(&run, "BackThrough", 12.0, 70.0, 1.75, 0.0);
    // Reversing from road 1 into the fork: lane −1 drives +s, so the straight arm.
    assert_esmini_pose_at(&run, "BackByLane", 12.0, 140.0, -1.75, std::f64::consts::PI);
    // The same with a route onto road 3: the curve.
    assert_esmini_pose_at(&run, "BackOnRoute", 8.0, 117.301, 6.819, 4.061);
    assert_esmini_pose_at(&run, "BackOnRoute", 12.0, 121.75, 25.836, 4.712);
    // Driving forward against road 3's lane −1 towards the fork: no connection, stuck.
    assert_esmini_pose_at(&run, "ForwardAgainstRoute", 12.0, 121.75, 20.0, 4.712);
    assert_matches_esmini("reversing_through_junctions.xosc", &run, 1e-3);
}

#[test]
fn junction_arms_include_esmini_counter_connections_in_its_order() {
    let run = run_fixture_scenario("junction_arms_one_way.xosc", 20.0);
    // Road 30 enters the junction only by counter connections: first the one towards road 20
    // (added while esmini checks road 20), then towards road 10. A route elsewhere takes the
    // first.
    assert_esmini_pose_at(&run, "FirstArm", 8.0, 107.745, -1.164, 2.422);
    assert_esmini_pose_at(&run, "FirstArm", 12.0, 88.463, 1.75, std::f64::consts::PI);
    // Without a route both arms turn 90°: esmini's seeded draw, in that order, picks road 10.
    assert_esmini_pose_at(&run, "TieDrawn", 12.0, 137.05, -1.75, 0.0);
    assert_esmini_pose_at(&run, "RoutedEast", 12.0, 137.05, -1.75, 0.0);
    // Reversing on road 10's lane −1 through the counter connection of road 101.
    assert_esmini_pose_at(&run, "BackIntoCounter", 12.0, 70.0, -1.75, 0.0);
    // Road 20's lane 1 has no connection at all.
    assert_esmini_pose_at(&run, "BackNoConnection", 12.0, 100.0, 1.75, std::f64::consts::PI);
    assert_matches_esmini("junction_arms_one_way.xosc", &run, 1e-3);
}

#[test]
fn entities_beside_the_lanes_follow_esmini_snapped_lanes() {
    let run = run_fixture_scenario("parking_bay_world_positions.xosc", 20.0);
    // Backing out of the border beside the bay lane −2, attached to lane −2 (the nearest
    // driving lane) at its offset; where lane −2 ends it joins lane −1's centre.
    assert_esmini_pose_at(&run, "OutOfBay", 4.0, 117.85, -12.704, 1.302);
    assert_esmini_pose_at(&run, "OutOfBay", 12.0, 134.55, -16.32, 0.802);
    assert_esmini_pose_at(&run, "BayLane", 8.0, 133.19, -14.979, 5.525);
    assert_esmini_pose_at(&run, "Straight", 12.0, 84.0, -9.5, 4.683);
    // The pedestrian put on the sidewalk is attached to lane −2 too (a teleport snaps to
    // driving lanes); when lane −2 ends its own types take it to the sidewalk's centre.
    assert_esmini_pose_at(&run, "Walker", 8.0, 119.217, -15.686, 5.922);
    assert_esmini_pose_at(&run, "Walker", 12.0, 124.564, -18.431, 5.622);
    assert_matches_esmini("parking_bay_world_positions.xosc", &run, 1e-3);
}

//! Where the ACC finds its lead across junctions (esmini's ControllerACC::Step asks
//! Position::Delta forward only). Each test: Ego's x and speed against esmini 3.6.0's run of
//! the same fixture.
//!
//! An ACC finds its lead on whichever branch of a junction it is: esmini's ControllerACC::Step
//! asks Position::Delta forward only, whose RoadPath::Calculate reaches the target's road
//! through any connection of the junction leading out of the ACC's road (not only the branch
//! the ACC would take), and carries the lane across that connection's lane link (dLaneId 0).
//! Fixture `acc_lead_on_other_branch.xosc` (the crossing): Ego's ACC (set speed 15 m/s) on
//! road 1 heading for the junction; Lead 4 m into the right turn (connecting road 102) at
//! 5 m/s, 45 m ahead along the roads: Ego brakes for it. Expected values: esmini 3.6.0 on the
//! same fixture (osc2cr found no lead before and kept 15 m/s).
//!
//! The ACC's lead search (Position::Delta, RoadPath::Calculate) walks a default junction's
//! connections as esmini holds them, with the counter connections it adds at load
//! (OpenDrive::CheckJunctionConnection): a connecting road that only leaves the junction onto
//! the ACC's road can be entered from that road too, by its far end, and its lanes are reached
//! through that counter connection's lane links. Fixture `acc_lead_on_counter_connection.xosc`
//! (the crossing): Ego's ACC (set speed 15 m/s) on road 1 heading for the junction; Lead on
//! connecting road 109 (road 4 to road 1) 4.4 m before its end, facing back towards road 4 at
//! 5 m/s: Ego brakes for it. Expected values: esmini 3.6.0 on the same fixture (osc2cr found
//! no lead before and kept 15 m/s).
//!
//! Across a direct junction the ACC's lead search (Position::Delta) carries its lane by the
//! junction's lane links to the linked road (Road::GetConnectingLaneId), and from the linked
//! road back by the counter connection esmini adds at load (lane links turned round): the lead
//! in the lane the ACC's lane leads to counts (dLaneId 0). Fixture
//! `acc_lead_across_direct_junction.xosc` (`direct_junction.xodr`): Ego's ACC (set speed
//! 15 m/s) in lane 1 of road 2 driving towards the junction; Lead in lane 1 of road 1, 40 m
//! ahead across it, at 5 m/s: Ego brakes for it. Expected values: esmini 3.6.0 on the same
//! fixture (osc2cr found no lane across the direct junction before and kept 15 m/s).

use crate::common::*;

/// Ego's (x, speed) at each (t, x, speed) of esmini's run of `fixture` on `map`.
fn assert_ego_follows(fixture: &str, map: &str, rows: &[(f64, f64, f64)]) {
    let run = run_fixture(fixture, map);
    for &(t, x, v) in rows {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 2e-3) && close(e.speed, v, 2e-3), "{fixture} t {t}: {e:?}");
    }
}

#[test]
fn an_acc_follows_a_lead_on_another_branch_of_a_junction() {
    assert_ego_follows(
        "acc_lead_on_other_branch.xosc",
        "crossing.xodr",
        &[(1.0, 46.381, 12.404), (2.0, 35.039, 10.368), (3.5, 21.377, 7.997), (4.0, 17.29, 8.886)],
    );
}

#[test]
fn an_acc_follows_a_lead_reached_through_a_counter_connection() {
    assert_ego_follows(
        "acc_lead_on_counter_connection.xosc",
        "crossing.xodr",
        &[(1.0, 46.274, 12.617), (2.0, 34.612, 10.789), (3.5, 20.109, 8.684), (4.0, 15.366, 10.341)],
    );
}

#[test]
fn an_acc_follows_a_lead_across_a_direct_junction() {
    assert_ego_follows(
        "acc_lead_across_direct_junction.xosc",
        "direct_junction.xodr",
        &[(1.0, 116.924, 11.628), (2.0, 106.325, 9.703), (3.0, 97.374, 8.276), (4.0, 89.669, 7.2)],
    );
}

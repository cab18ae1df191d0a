//! SynchronizeAction whose master drives against its lane's driving direction, exactly: esmini's
//! SynchronizeAction::Step measures the master's way to its target along the road and turns the
//! sign when the master faces more than a right angle from its lane's driving direction
//! (Position::GetDrivingDirection), testing the heading the master's position holds — composed
//! with the road's through esmini's matrices, a micro-radian off the road's on a road along ±y.
//! On an exact tie (a heading of π from the driving direction) that micro-radian decides.
//!
//! Fixture `synchronize_master_against_its_lane.xosc` on `tee_lht.xodr` (difftest's
//! left-hand-traffic T; road 3 runs along −y, its lane −1 drives towards +y): Car1, an ACC
//! controller's car, starts at −2.21 m/s and then drives along s at 13.92 m/s, against its lane;
//! Car0 drives its lane at 6.12 m/s and synchronises from t = 5.42 s to Car1's target across the
//! junction. In esmini's run (3.6.0) Car0 stops at once and stands to the end: the master's speed
//! towards its target counts as negative, so the actor waits for it to move (the action's
//! waiting mode). Main read the tie the other way and let Car0 drive on. The numbers are
//! esmini's.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn the_actor_stands_when_its_master_drives_exactly_against_its_lane() {
    assert_fixture_matches_esmini(
        "synchronize_master_against_its_lane.xosc",
        9.0,
        &[
            ("Car0", 5.42, -1.75, -143.0696, 1.570797),
            // Stopped in the step the action starts, and standing to the end.
            ("Car0", 5.43, -1.75, -143.0696, 1.570797),
            ("Car0", 8.83, -1.75, -143.0696, 1.570797),
            ("Car1", 8.83, -1.75, -223.134304, 4.71239),
        ],
    );
}

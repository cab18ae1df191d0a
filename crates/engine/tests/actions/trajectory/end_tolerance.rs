//! A timed FollowTrajectoryAction ends when its time plus the offset passes the last stamp
//! less esmini's SMALL_NUMBER (1e-6; FollowTrajectoryAction::Step). Fixture
//! `timed_trajectory_end_tolerance.xosc`: Ego on a polyline whose last stamp is 1.0000005 s
//! (relative timing); Flag at 1 m/s is sped to 10 m/s when the action ends. esmini ends it at
//! 1.00 s, so Flag is at 101.1 at 1.01 s (with a margin of 1e-9 it ended a step later).
//! Expected values: esmini 3.6.0 on the fixture (x).

use crate::common::*;

#[test]
fn a_timed_trajectory_ends_within_small_number_of_its_last_stamp() {
    let run = run_fixture_on("timed_trajectory_end_tolerance.xosc", "straight.xodr", 2.0);
    for (t, x) in [(1.0, 101.0), (1.01, 101.1), (1.5, 106.0)] {
        let e = at(&run, "Flag", t);
        assert!(close(e.x, x, 1e-6), "Flag at {t}: x {}, esmini {x}", e.x);
    }
}

//! An ACC finds its lead on whichever branch of a junction it is: esmini's ControllerACC::Step
//! asks Position::Delta forward only, whose RoadPath::Calculate reaches the target's road
//! through any connection of the junction leading out of the ACC's road (not only the branch
//! the ACC would take), and carries the lane across that connection's lane link (dLaneId 0).
//! Fixture `acc_lead_on_other_branch.xosc` (the crossing): Ego's ACC (set speed 15 m/s) on
//! road 1 heading for the junction; Lead 4 m into the right turn (connecting road 102) at
//! 5 m/s, 45 m ahead along the roads: Ego brakes for it. Expected values: esmini 3.6.0 on the
//! same fixture (osc2cr found no lead before and kept 15 m/s).

use crate::common::*;

#[test]
fn an_acc_follows_a_lead_on_another_branch_of_a_junction() {
    let run = run_fixture("acc_lead_on_other_branch.xosc", "crossing.xodr");
    for (t, x, v) in [(1.0, 46.381, 12.404), (2.0, 35.039, 10.368), (3.5, 21.377, 7.997), (4.0, 17.29, 8.886)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 2e-3) && close(e.speed, v, 2e-3), "t {t}: {e:?}");
    }
}

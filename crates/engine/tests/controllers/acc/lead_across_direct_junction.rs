//! Across a direct junction the ACC's lead search (Position::Delta) carries its lane by the
//! junction's lane links to the linked road (Road::GetConnectingLaneId), and from the linked
//! road back by the counter connection esmini adds at load (lane links turned round): the lead
//! in the lane the ACC's lane leads to counts (dLaneId 0). Fixture
//! `acc_lead_across_direct_junction.xosc` (`direct_junction.xodr`): Ego's ACC (set speed
//! 15 m/s) in lane 1 of road 2 driving towards the junction; Lead in lane 1 of road 1, 40 m
//! ahead across it, at 5 m/s: Ego brakes for it. Expected values: esmini 3.6.0 on the same
//! fixture (osc2cr found no lane across the direct junction before and kept 15 m/s).

use crate::common::*;

#[test]
fn an_acc_follows_a_lead_across_a_direct_junction() {
    let run = run_fixture("acc_lead_across_direct_junction.xosc", "direct_junction.xodr");
    for (t, x, v) in [(1.0, 116.924, 11.628), (2.0, 106.325, 9.703), (3.0, 97.374, 8.276), (4.0, 89.669, 7.2)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 2e-3) && close(e.speed, v, 2e-3), "t {t}: {e:?}");
    }
}

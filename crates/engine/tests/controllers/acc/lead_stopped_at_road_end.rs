//! An ACC behind a lead whose own ACC (override mode) stands at the road's end (fixture
//! `acc_follows_lead_stopped_at_road_end.xosc`, straight road of 1000 m: Ego, additive ACC, from
//! s = 900 at 20 m/s; Target, override ACC, from s = 960 at 20 m/s, at the end from 2.00 s).
//! esmini's ScenarioEngine::step gives the stuck Target speed 0 before it steps any controller,
//! so Ego's ACC, stepped first, sees the lead standing and brakes at its full 5 m/s², although
//! Target's own ACC then puts back the speed it brakes from. Expected values: esmini 3.6.0.

use crate::common::*;

#[test]
fn the_follower_sees_the_lead_stopped_at_the_road_end_before_its_acc_steps() {
    let run = run_fixture("acc_follows_lead_stopped_at_road_end.xosc", "straight.xodr");
    // (time, x, speed) of Ego; was 20 m/s on until the gap closed
    for (t, x, v) in [(2.01, 940.2, 20.0), (2.02, 940.4, 19.951), (2.03, 940.6, 19.901), (3.0, 957.613175, 15.169869), (6.0, 985.082614, 4.338134)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-3) && close(e.speed, v, 1e-3), "t {t}: {e:?}, esmini x {x} speed {v}");
    }
}

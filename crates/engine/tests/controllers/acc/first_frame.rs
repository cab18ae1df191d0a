//! An ACC steps in the first frame too (dt 0), as every active controller in esmini's
//! ScenarioEngine::step: a lead vehicle closer than 1 m (bounding box to bounding box) stops
//! its entity at once (ControllerACC::Step sets its speed to 0), in additive and override mode.
//! Fixture `acc_first_frame.xosc` (straight road): Ego (additive) and Ego2 (override), each at
//! 10 m/s with a lead at 8 m/s 0.65 m ahead of its bounding box; the ACC then follows as the
//! gap opens. Expected values: esmini 3.6.0 on the same fixture (osc2cr stepped the ACC only
//! from the second frame, when the lead already overlapped: it never saw it and drove on at
//! 10 m/s).

use crate::common::*;

#[test]
fn an_acc_stops_for_a_close_lead_in_the_first_frame() {
    let run = run_fixture("acc_first_frame.xosc", "straight.xodr");
    for (name, rows) in [
        ("Ego", [(0.0, 10.0, 0.0), (0.5, 10.395131, 1.725665), (2.0, 16.345248, 5.819744), (6.0, 46.960742, 8.217812)]),
        ("Ego2", [(0.0, 10.0, 0.0), (0.5, 10.264757, 1.189099), (2.0, 15.523995, 5.652792), (6.0, 47.060322, 8.317366)]),
    ] {
        for (t, x, v) in rows {
            let e = at(&run, name, t);
            assert!(close(e.x, x, 2e-3) && close(e.speed, v, 2e-3), "{name} t {t}: {e:?}");
        }
    }
}

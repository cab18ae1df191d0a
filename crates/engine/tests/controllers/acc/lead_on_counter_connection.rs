//! The ACC's lead search (Position::Delta, RoadPath::Calculate) walks a default junction's
//! connections as esmini holds them, with the counter connections it adds at load
//! (OpenDrive::CheckJunctionConnection): a connecting road that only leaves the junction onto
//! the ACC's road can be entered from that road too, by its far end, and its lanes are reached
//! through that counter connection's lane links. Fixture `acc_lead_on_counter_connection.xosc`
//! (the crossing): Ego's ACC (set speed 15 m/s) on road 1 heading for the junction; Lead on
//! connecting road 109 (road 4 to road 1) 4.4 m before its end, facing back towards road 4 at
//! 5 m/s: Ego brakes for it. Expected values: esmini 3.6.0 on the same fixture (osc2cr found
//! no lead before and kept 15 m/s).

use crate::common::*;

#[test]
fn an_acc_follows_a_lead_reached_through_a_counter_connection() {
    let run = run_fixture("acc_lead_on_counter_connection.xosc", "crossing.xodr");
    for (t, x, v) in [(1.0, 46.274, 12.617), (2.0, 34.612, 10.789), (3.5, 20.109, 8.684), (4.0, 15.366, 10.341)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 2e-3) && close(e.speed, v, 2e-3), "t {t}: {e:?}");
    }
}

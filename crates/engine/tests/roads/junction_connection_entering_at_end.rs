//! A junction connection is taken as the file gives it: an entity leaving its road into a
//! default junction enters the connecting road at the contact point the connection names,
//! even where that road's own links do not lead back to the incoming road (esmini's
//! Position::MoveToConnectingRoad over Junction::GetRoadConnectionByIdx: it reads the
//! junction's connections only). Entering at the end, it drives the connecting road against
//! its s, facing back. Found by crates/difftest (s33033_00292, s34034_00126, s34034_00684 on
//! SampleDatabase.xodr: junction 7 lets road 170 in at the end of connecting road 148, whose
//! start lies where road 170 ends; esmini jumped 5 m to that end, the engine stopped at road
//! 170's end). Fixture `junction_connection_entering_at_end.xosc` on
//! `connection_contact_end.xodr`: road 1 (100 m along +x) into junction 7, whose one
//! connection enters connecting road 2 (x 100 to 110) at its end; Car on road 1 at 10 m/s
//! from s = 90. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

const CAR: [(f64, f64, f64, f64); 4] = [(1.0, 100.0, -1.75, 10.0), (1.01, 109.9, -1.75, 10.0), (1.1, 109.0, -1.75, 10.0), (2.0, 100.0, -1.75, 10.0)];

#[test]
fn a_connection_naming_the_far_end_is_entered_there() {
    let run = run_fixture_on("junction_connection_entering_at_end.xosc", "connection_contact_end.xodr", 2.0);
    assert_esmini_rows(&run, "Car", &CAR, 1e-6);
    let e = at(&run, "Car", 1.1);
    assert!(close(e.h, std::f64::consts::PI, 1e-6), "{e:?}");
}

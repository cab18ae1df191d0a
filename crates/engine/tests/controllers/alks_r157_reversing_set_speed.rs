//! An ALKS_R157SM_Controller activated while its entity reverses keeps the negative set speed:
//! Model::Cruise returns `CLAMP(speed + acc·dt, 0, set_speed_)`, and esmini's CLAMP is
//! `MIN(hi, MAX(lo, x))`, which gives `hi` when it is below `lo` — so the model cruises at its
//! set speed, the entity's speed at activation (ControllerALKS_R157SM::Activate), instead of
//! stopping. Fixture `alks_r157_reversing_set_speed.xosc` (straight road): "Reverser" at
//! −4.5 m/s, its ReferenceDriver model activated on the lateral domain only at 1 s (moved by the
//! model and by the default controller: twice its speed); "Forward" at −3 m/s with a Regulation
//! model active on both domains from the start. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn an_alks_r157_activated_while_reversing_cruises_at_the_negative_speed() {
    let run = run_fixture_on("alks_r157_reversing_set_speed.xosc", "straight.xodr", 4.0);
    for (name, t, x, v) in [
        ("Reverser", 1.0, 295.5, -4.5),
        ("Reverser", 1.02, 295.365, -4.5),
        ("Reverser", 4.0, 268.545, -4.5),
        ("Forward", 1.0, 297.0, -3.0),
        ("Forward", 4.0, 288.0, -3.0),
    ] {
        let s = at(&run, name, t);
        assert!(close(s.x, x, 1e-6) && close(s.speed, v, 1e-9), "{name} at {t}: {s:?}");
    }
}

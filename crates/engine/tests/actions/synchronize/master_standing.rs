//! SynchronizeAction while its master stands still, against esmini 3.6.0's own run of
//! `fixtures/synchronize_master_standing.xosc` (straight road; both actions start at t > 1 s,
//! their masters stand until a speed step to 10 m/s at t > 3 s; `esmini-3.6.0
//! --fixed_timestep 0.01`, its CSV log's values, 6 decimals). esmini stops the actor at once
//! (SynchronizeAction::Step: "Waiting for master to move"), with or without a final speed, and
//! counts the master as moving once its velocity — derived from its last step's motion — is
//! not zero: one step after it got its speed.
//! - Actor1 (10 m/s) must reach s = 400 when Master1 reaches s = 300, at 15 m/s;
//! - Actor2 (8 m/s) must reach s = 750 when Master2 reaches s = 700, no final speed.

use crate::common::*;

fn run_fixture() -> engine::Run {
    run_straight_fixture("synchronize_master_standing.xosc", 30.0)
}

/// (entity, time, x, speed) rows of esmini's log.
const ESMINI: &[(&str, f64, f64, f64)] = &[
    ("Actor1", 1.01, 60.1, 10.0),
    ("Actor1", 1.02, 60.1, 0.0),
    ("Actor1", 3.02, 60.1, 0.0),
    ("Actor1", 3.03, 60.100216, 0.021621),
    ("Actor1", 4.0, 61.148808, 2.118789),
    ("Actor1", 10.0, 112.837137, 15.088038),
    ("Actor1", 23.01, 400.0, 15.0),
    ("Actor1", 25.0, 429.85, 15.0),
    ("Actor2", 1.02, 458.08, 0.0),
    ("Actor2", 3.02, 458.08, 0.0),
    ("Actor2", 3.03, 458.080146, 0.014611),
    ("Actor2", 4.0, 458.788755, 1.431822),
    ("Actor2", 10.0, 493.720187, 10.197031),
    ("Actor2", 23.01, 750.0, 29.101678),
    ("Actor2", 25.0, 807.912339, 29.101678),
];

#[test]
fn the_actor_waits_for_its_master_as_in_esminis_log() {
    let run = run_fixture();
    assert_esmini_x_speed(&run, ESMINI, 2e-6);
    // Both end when the masters arrive, at 23 s in esmini's log.
    for name in ["Sync1Action", "Sync2Action"] {
        let end = event_time(&run, name, "end");
        assert!(end.is_some_and(|e| close(e, 23.0, 1e-9)), "{name}: {end:?}");
    }
}

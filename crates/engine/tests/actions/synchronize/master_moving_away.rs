//! SynchronizeAction whose master drives away from its target, against esmini 3.6.0's own run
//! of `fixtures/synchronize_master_moving_away.xosc` (straight road; `esmini-3.6.0
//! --fixed_timestep 0.01`, its CSV log's values). SynchronizeAction::Step signs the master's
//! speed with the direction of Position::Delta (RoadPath::Calculate: on one road, the s
//! difference seen the way the master faces): a target behind the master counts as a master
//! that does not approach, so the actor stops at once ("Waiting for master to move"); the next
//! step the master's distance has grown and the action ends (with the final speed if any).
//! - Master1 (lane -2, +s, 10 m/s) from s = 300 towards s = 200; Actor1 (12 m/s, final 15);
//! - Master2 (lane 1, facing -s, 10 m/s) from s = 900 towards s = 950; Actor2 (8 m/s, none).

use crate::common::*;

/// (entity, time, x, speed) rows of esmini's log.
const ESMINI: &[(&str, f64, f64, f64)] = &[
    ("Actor1", 1.01, 62.12, 12.0),
    ("Actor1", 1.02, 62.12, 0.0),
    ("Actor1", 1.03, 62.27, 15.0),
    ("Actor1", 5.0, 121.82, 15.0),
    ("Actor2", 1.01, 508.08, 8.0),
    ("Actor2", 1.02, 508.08, 0.0),
    ("Actor2", 5.0, 508.08, 0.0),
];

#[test]
fn a_master_driving_away_from_its_target_stops_the_actor_as_in_esminis_log() {
    let run = run_straight_fixture("synchronize_master_moving_away.xosc", 5.0);
    assert_esmini_x_speed(&run, ESMINI, 2e-6);
}

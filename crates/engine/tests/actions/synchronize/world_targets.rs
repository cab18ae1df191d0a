//! SynchronizeAction whose targets are WorldPositions beside the lanes the entities drive in,
//! against esmini 3.6.0's own run of `fixtures/synchronize_world_targets.xosc` (straight road;
//! `esmini-3.6.0 --fixed_timestep 0.01`, its CSV log's values). esmini's target positions are
//! roadmanager::Positions attached to the road where they lie (Position::SetInertiaPos), so
//! SynchronizeAction::Step measures both distances along the road (Position::Delta): a target
//! 7 m to the side counts by its s alone, not by the straight line to it.
//! - Actor1 (lane -1, s 50, 10 m/s) to (110, 5.25) in lane 2 when Master1 (lane -2, s 20,
//!   20 m/s) reaches (250, 1.75) in lane 1; no final speed;
//! - Actor2 (lane -1, s 500, 12 m/s) to (560, 1.75) when Master2 (lane -2, s 520, 15 m/s)
//!   reaches (640, 5.25); final speed 6 m/s.

use crate::common::*;

/// (entity, time, x, speed) rows of esmini's log.
const ESMINI: &[(&str, f64, f64, f64)] = &[
    ("Actor1", 2.0, 69.505196, 9.010408),
    ("Actor1", 5.0, 92.024110, 6.012434),
    ("Actor1", 8.0, 105.552113, 3.016853),
    ("Actor1", 10.0, 109.581959, 1.024133),
    ("Actor2", 3.0, 532.674969, 8.675495),
    ("Actor2", 6.0, 551.171410, 3.676488),
    ("Actor2", 9.0, 566.0, 6.0),
    ("Actor2", 12.0, 584.0, 6.0),
];

#[test]
fn world_targets_are_measured_along_the_road_as_in_esminis_log() {
    let run = run_straight_fixture("synchronize_world_targets.xosc", 12.0);
    assert_esmini_x_speed(&run, ESMINI, 2e-6);
}

//! SynchronizeAction whose master, or actor, follows a trajectory, against esmini 3.6.0's own
//! run of `fixtures/synchronize_on_trajectories.xosc` (straight road; `esmini-3.6.0
//! --fixed_timestep 0.01`, its CSV log's values). SynchronizeAction::Step measures the distance
//! of an entity on a trajectory along that trajectory (Position::Distance in the trajectory
//! frame: the s of the path's point nearest the target less the entity's s on the path), not
//! along the road: both zigzag polylines are longer than the road they follow.
//! - Master1 (lane -1, s 20, 10 m/s) follows the zigzag Zigzag1 from 0.5 s (TimeReference
//!   None: lateral only) and is the master of both actions; its target, lane 1 at s 250, lies
//!   on the path's last leg: it arrives at 23.76 s, not at 23.5 s as along the road.
//! - Actor1 (lane -2, s 0, 10 m/s) to lane -2 at s 200, final speed 8 m/s;
//! - Actor2 (lane -2, s 400, 10 m/s) follows Zigzag2 from 0.5 s and synchronises (no final
//!   speed) to lane -2 at s 600, 3.5 m beside its path's last leg.

use crate::common::*;

/// (entity, time, x, speed) rows of esmini's log.
const ESMINI: &[(&str, f64, f64, f64)] = &[
    ("Actor1", 2.0, 19.919453, 9.838906),
    ("Actor1", 8.0, 75.853797, 8.723144),
    ("Actor1", 14.0, 124.851289, 7.810767),
    ("Actor1", 20.0, 170.487960, 7.662346),
    ("Actor1", 23.76, 199.933455, 7.999255),
    ("Actor1", 23.77, 200.013455, 8.0),
    ("Actor2", 2.0, 414.845464, 9.888702),
    ("Actor2", 8.0, 470.259954, 9.132767),
    ("Actor2", 14.0, 520.985998, 8.467679),
    ("Actor2", 20.0, 570.366652, 7.991864),
    ("Actor2", 25.0, 609.404116, 7.697680),
];

#[test]
fn distances_on_a_trajectory_are_measured_along_it_as_in_esminis_log() {
    let run = run_straight_fixture("synchronize_on_trajectories.xosc", 26.0);
    assert_esmini_x_speed(&run, ESMINI, 2e-6);
    let end = event_time(&run, "ASync1", "end").expect("the action ends");
    assert!(close(end, 23.76, 1e-9), "ends at {end}, esmini at 23.76 s");
}

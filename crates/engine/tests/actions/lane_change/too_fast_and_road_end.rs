//! LaneChangeAction whose shape asks for more sideways motion than the speed allows, and one
//! that meets the end of the road, against esmini 3.6.0's own run of
//! `fixtures/lane_change_fast_and_road_end.xosc` (straight road; every change starts at
//! t > 1 s; `esmini-3.6.0 --fixed_timestep 0.01`, its CSV log's values, 6 decimals):
//! - SinFast (2 m/s, sinusoidal over 0.5 s), LinFast (1 m/s, linear over 1 s), CubRate (3 m/s,
//!   cubic at 5 m/s lateral): where the rate exceeds the speed esmini moves the car sideways
//!   only, speed·dt a step on the straight line from start to target, facing ±(π/2 − 1e-6)
//!   (LatLaneChangeAction::Step, "requested lateral motion too large wrt speed");
//! - AtEnd (over 50 m) and AtEndTime (over 3 s) reach the road's end mid-change: the action
//!   ends there (POS_STATUS_END_OF_ROAD → OSCAction::End), the offset and heading kept.

use crate::common::*;

fn run_fixture() -> engine::Run {
    run_straight_fixture("lane_change_fast_and_road_end.xosc", 10.0)
}

/// (entity, time, x, y, heading) rows of esmini's log.
const ESMINI: &[(&str, f64, f64, f64, f64)] = &[
    ("SinFast", 1.05, 102.073265, -1.98, 4.71239),
    ("SinFast", 2.0, 102.073265, -3.88, 4.71239),
    ("SinFast", 3.0, 102.875973, -5.25, 0.0),
    ("LinFast", 1.05, 201.01, -1.79, 4.71239),
    ("LinFast", 3.0, 201.01, -3.74, 4.71239),
    ("CubRate", 1.05, 303.149189, -5.235149, 0.186106),
    ("CubRate", 1.3, 303.483833, -4.313333, 1.570795),
    ("CubRate", 2.0, 303.552795, -1.90646, 0.909014),
    ("CubRate", 3.0, 306.503719, -1.75, 0.0),
    ("AtEnd", 1.3, 992.999817, -1.778967, 6.263944),
    ("AtEnd", 2.0, 999.992978, -2.077335, 6.219801),
    ("AtEnd", 3.0, 1000.0, -2.083753, 6.219242),
    ("AtEndTime", 1.3, 995.397733, -5.158206, 0.074112),
    ("AtEndTime", 3.0, 1000.0, -4.523211, 0.181152),
];

#[test]
fn lane_changes_follow_esmini_log() {
    assert_esmini_poses(&run_fixture(), ESMINI, 2e-6, 2e-5);
}

#[test]
fn lane_changes_end_when_esmini_ends_them() {
    let run = run_fixture();
    // esmini's log: endTransition of each action.
    for (name, t) in [("ChangeAtEndTime", 1.88), ("ChangeAtEnd", 2.0), ("ChangeCubRate", 2.13), ("ChangeSinFast", 2.61), ("ChangeLinFast", 4.5)] {
        let end = event_time(&run, name, "end");
        assert!(end.is_some_and(|e| close(e, t, 1e-9)), "{name}: {end:?}, esmini {t}");
    }
    // Ended at the road's end with speed left: the car stands there afterwards.
    assert!(close(at(&run, "AtEnd", 3.0).speed, 0.0, 1e-12));
}

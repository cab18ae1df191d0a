//! LateralDistanceAction in the entity coordinate system, and in one esmini 3.6.0 does not act
//! on, against esmini's own run of `fixtures/lat_distance_entity_frame.xosc` (straight road;
//! each actor starts its action at t > 1 s, 10 m/s; `esmini-3.6.0 --fixed_timestep 0.01`; the
//! expected values are its CSV log's, 6 decimals):
//! - ActA, no constraints: jumps onto the line 2 m left of RefA, whose heading is 0.05 rad,
//!   and drives along it facing 0.05;
//! - ActB, maxAcceleration 2: curves towards the line 1 m (+ half the two widths) right of RefB,
//!   within the turn radius from the start (the blended heading);
//! - ActC, maxAcceleration 50: heads straight at the line 8 m left of RefC, turning 0.05 rad a
//!   step, then settles on it;
//! - ActD, lane coordinates: esmini's step does nothing; the entity drives on in its lane.

use crate::common::*;

fn run_fixture() -> engine::Run {
    run_straight_fixture("lat_distance_entity_frame.xosc", 10.0)
}

/// (entity, time, x, y, heading) rows of esmini's log.
const ESMINI: &[(&str, f64, f64, f64, f64)] = &[
    ("ActA", 1.01, 30.1, -1.75, 0.0),
    ("ActA", 1.02, 30.2571, -4.889386, 0.05),
    ("ActA", 1.03, 30.353182, -4.888581, 0.05),
    ("ActA", 2.0, 39.673089, -4.810521, 0.05),
    ("ActA", 8.0, 97.322003, -4.327672, 0.05),
    ("ActB", 1.02, 210.2, -1.7502, 6.281185),
    ("ActB", 2.0, 219.96153, -2.544518, 6.181775),
    ("ActB", 4.0, 239.913589, -3.884858, 6.241872),
    ("ActB", 8.0, 279.904758, -4.626283, 6.277077),
    ("ActC", 1.02, 410.199875, -5.245002, 0.05),
    ("ActC", 1.03, 410.299375, -5.235019, 0.1),
    ("ActC", 2.0, 414.011873, 2.554418, 0.226089),
    ("ActC", 3.0, 424.001164, 2.749938, 0.000131),
    ("ActC", 8.0, 474.001163, 2.749994, 6.283067),
    ("ActD", 8.0, 680.0, -1.75, 0.0),
];

#[test]
fn entity_frame_follows_esmini_log() {
    let run = run_fixture();
    assert_esmini_poses(&run, ESMINI, 2e-6, 2e-6);
    // The actions drive along at the entity's speed.
    for &(name, t, ..) in ESMINI {
        assert!(close(at(&run, name, t).speed, 10.0, 1e-12), "{name} at {t}: speed {}", at(&run, name, t).speed);
    }
}

#[test]
fn entity_frame_actions_never_end_and_only_the_lane_frame_warns() {
    let run = run_fixture();
    // esmini calls no End in the entity frame, even for a non-continuous action (ActB).
    for name in ["KeepActA", "KeepActB", "KeepActC", "KeepActD"] {
        assert!(event_time(&run, name, "end").is_none(), "{name} ended");
    }
    let w: Vec<_> = run.warnings.iter().map(|w| w.to_string()).filter(|w| w.contains("LateralDistanceAction")).collect();
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("Lane"), "{w:?}");
}

//! The speed of an entity that drives into the end of a road, against esmini 3.6.0's own run
//! of `fixtures/end_of_road_speed.xosc` (straight 1 km road, four cars at 10 m/s reaching
//! either end exactly on a step or within one; `esmini-3.6.0 --fixed_timestep 0.01`, its CSV
//! log's values). ScenarioEngine::step stops an entity only once it is already flagged at the
//! end of the road and its velocity (the last step's) is zero: the speed drops two steps after
//! the arrival, which a SpeedCondition sees.

use crate::common::*;

/// (entity, time, speed) rows of esmini's log; each car arrives two steps before its zero.
const ESMINI: &[(&str, f64, f64)] = &[
    // lane -1 from s = 995: s = 1000 exactly at 0.50 s
    ("Actor1", 0.50, 10.0),
    ("Actor1", 0.51, 10.0),
    ("Actor1", 0.52, 0.0),
    // lane 1 (facing -s) from s = 5: s = 0 exactly at 0.50 s
    ("Actor2", 0.51, 10.0),
    ("Actor2", 0.52, 0.0),
    // lane -2 from s = 990.005: the end within the step to 1.00 s
    ("Master1", 1.01, 10.0),
    ("Master1", 1.02, 0.0),
    // lane 1 from s = 10.004: the end within the step to 1.01 s
    ("Master2", 1.02, 10.0),
    ("Master2", 1.03, 0.0),
    ("Master2", 2.0, 0.0),
];

#[test]
fn an_entity_at_the_road_end_stops_two_steps_after_arriving_as_in_esminis_log() {
    let run = run_straight_fixture("end_of_road_speed.xosc", 2.0);
    for &(name, t, v) in ESMINI {
        let s = at(&run, name, t);
        assert!(close(s.speed, v, 1e-9), "{name} at {t}: speed {} against esmini {v}", s.speed);
    }
}

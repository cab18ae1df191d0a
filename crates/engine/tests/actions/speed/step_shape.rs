//! A SpeedAction of step shape ends in its first step whatever span the file gives it:
//! esmini's ScenarioReader::ParseTransitionDynamics reads a step's value as 0. Fixture
//! `speed_step_with_time.xosc` (straight road, Ego at 10 m/s, maxAcceleration and
//! maxDeceleration 5 m/s²): at t > 1 a step SpeedAction "over 3 s" to 20 m/s; a second event,
//! started when the first action completes, slows to 12 m/s at 2 m/s². Expected values:
//! esmini 3.6.0 on the same fixture (`esmini_run_one.py … --max_time 8`).

use crate::common::*;

#[test]
fn a_step_speed_action_with_a_time_span_ends_at_once() {
    let run = run_straight_fixture("speed_step_with_time.xosc", 8.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini: 20 m/s at 1.02 s; the step action completes at 1.01 s, so the slowing starts at
    // 1.02 s: 19.98 m/s at 1.03 s (x 20.4998), 18.04 at 2.0 s, 12.0 from 5.01 s (x 96.02 at 6 s).
    assert!(close(at(&run, "Ego", 1.02).speed, 20.0, 1e-12));
    let e = at(&run, "Ego", 1.03);
    assert!(close(e.speed, 19.98, 1e-9) && close(e.x, 20.4998, 1e-6), "{e:?}");
    assert!(close(at(&run, "Ego", 2.0).speed, 18.04, 1e-9));
    let e = at(&run, "Ego", 6.0);
    assert!(close(e.speed, 12.0, 1e-9) && close(e.x, 96.02, 1e-6), "{e:?}");
}

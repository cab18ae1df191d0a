//! While a ghost restart rewinds time, injected actions still step and a FollowGhost car in
//! position mode loses its trail for one step:
//! - ScenarioEngine::step steps its injected actions whatever the ghost mode, and
//!   LatLaneChangeAction::Step returns early only for a non-ghost while the time before the
//!   step is below 0: a NaturalDriver's lane change goes on in the rewound run once that time
//!   reaches 0 (the engine froze it with the controllers);
//! - the restart's teleport clears the ghost's trail, and ControllerFollowGhost's
//!   FindPointAhead on an empty trail answers "past the end", not an error: the target point
//!   stays a default vertex, the world origin at speed 0 (the engine steered at the car itself).
//!
//! Found by a helper on s67067_00094. Fixture `ghost_restart_steps_injected_lane_change.xosc`
//! on difftest_straight.xodr, esmini 3.6.0's numbers: Car0 (NaturalDriver) changes lane, Car2
//! follows its ghost (head start 2 s, position mode); the ghost restarts at 1.22 s.

use crate::common::oracle::{assert_esmini_pose_at, run_fixture_scenario};
use crate::common::*;

/// Sample of `entity` at time `t` of the (only) replay.
fn replayed(run: &engine::Run, entity: &str, t: f64) -> engine::Sample {
    let i = run.trace.entities.iter().position(|e| e.name == entity).expect("entity in trace");
    let r = run.trace.replays.first().expect("a replay");
    let j = ((t - r.start) / run.trace.step).round() as usize;
    r.rows.get(j).and_then(|row| row.get(i)).copied().flatten().expect("replayed sample exists")
}

#[test]
fn the_lane_change_goes_on_in_the_rewound_run_and_the_follower_steers_at_the_origin() {
    let run = run_fixture_scenario("ghost_restart_steps_injected_lane_change.xosc", 3.0);
    // rewound time -0.76 s: still where the restart found it; from time 0 on it moves sideways
    for (t, x, y) in [(-0.76, 64.637347, -2.959220), (0.01, 64.636080, -2.976679), (0.5, 70.473573, -3.863845), (1.21, 78.960994, -4.926474)] {
        let s = replayed(&run, "Car0", t);
        assert!(close(s.x, x, 1e-3) && close(s.y, y, 1e-3), "Car0 at replayed {t} s: ({:.6}, {:.6}), esmini ({x}, {y})", s.x, s.y);
    }
    // after the replay: the follower, steered once at the origin, is where esmini has it
    let s = at(&run, "Car2", 2.0);
    assert!(close(s.x, 40.788379, 1e-3) && close(s.y, -8.733038, 1e-3), "Car2 at 2 s: ({:.6}, {:.6})", s.x, s.y);
    assert_esmini_pose_at(&run, "Car0", 2.0, 88.591055, -5.25, 0.0);
}

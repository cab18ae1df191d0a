//! A lane change onto a lane the entity does not snap to (a border lane, a sidewalk) leaves it
//! in the driving lane beside, at a large offset (esmini's LatLaneChangeAction::Step attaches
//! the entity by Position::XYZ2TrackPos to the nearest lane of its snapping types when it has
//! no route), so its ACC keeps following the vehicle ahead in that lane. Fixture
//! `acc_lane_change_off_driving_lanes.xosc` (`bay.xodr`: driving lanes −1 and −2, border −3,
//! sidewalk −4): Ego's ACC (override, 10 m/s) in lane −2 at s = 10; a parked Target in lane −2
//! at s = 80; at t > 0.5 Ego changes to the border lane −3 in 1 s. Expected values: esmini
//! 3.6.0 on the same fixture (`--fixed_timestep 0.01`).

use crate::common::*;

#[test]
fn an_acc_follows_on_after_a_lane_change_onto_a_border_lane() {
    let run = run_fixture_on("acc_lane_change_off_driving_lanes.xosc", "bay.xodr", 11.0);
    assert!(run.warnings.is_empty(), "{:?}", run.warnings);
    // esmini's rows (x, y, speed): at the border lane's centre (y = −7.5), braking behind Target.
    for (t, x, v) in [(1.51, 24.802538, 10.0), (4.0, 49.478482, 9.112807), (6.0, 63.17521, 4.712664), (8.0, 69.37906, 1.821998), (10.0, 71.561962, 0.577567)] {
        let e = at(&run, "Ego", t);
        assert!(close(e.x, x, 1e-4) && close(e.y, -7.5, 1e-6) && close(e.speed, v, 1e-4), "Ego at {t}: {e:?}, esmini ({x}, -7.5, {v})");
    }
    // esmini's log: lane −2, offset −2.5 m.
    let lane = at(&run, "Ego", 10.0).road;
    assert!(lane.is_some_and(|l| l.lane_id == -2 && close(l.lane_offset, -2.5, 1e-6)), "{lane:?}");
}

//! A heading handed on across roads (fixture `heading_across_road.xosc` on `crossing.xodr`):
//! Car0 stands on road 2, whose reference heading 1.5707963268 lies a hair past π/2, and Car1,
//! placed by a RelativeObjectPosition from it onto lane −1 of road 1 (along +x), takes its
//! heading. esmini's position holds it as π/2 + 1e-6 (Position::EvaluateHPR's guard against
//! gimbal lock), which IsAngleForward counts as facing against road 1's s, so the default
//! controller drives Car1 towards −x. Expected values: esmini 3.6.0 on the fixture.

use crate::common::*;

#[test]
fn a_heading_a_hair_past_a_right_angle_faces_against_the_road() {
    let run = run_fixture("heading_across_road.xosc", "crossing.xodr");
    // (time, x): was 50.1 at 0.01 s, driving along +x
    for (t, x) in [(0.0, 50.000032), (0.01, 49.900032), (1.0, 40.000032), (2.0, 30.000032)] {
        let e = at(&run, "Car1", t);
        assert!(close(e.x, x, 1e-3) && close(e.y, -1.749952, 1e-3), "t {t}: {e:?}, esmini x {x}");
    }
}

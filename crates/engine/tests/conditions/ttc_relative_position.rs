//! A TimeToCollisionCondition to a position placed relative to an entity measures to the world
//! origin: esmini's TrigByTimeToCollision::CheckCondition reads the position's x and y without
//! Position::EvaluateRelation, and the OSCPositionRelative* constructors only set up the
//! relation, so the point keeps Position::Init's (0, 0). An absolute position is where it says.
//! Found by crates/difftest (s26026_00576 on e6mini.xodr). Fixture `ttc_relative_position.xosc`
//! on `straight.xodr` (starting at the origin along +x): Ego drives −x on lane 1 at 20 m/s from
//! x 299.93 towards a point 10 m short of a standing car at x 250 (TTC 2 s if it were there);
//! Twin, reversing at 20 m/s on lane −2 from the same x, watches the absolute point s 240 (TTC
//! 3 s). Rule: TTC < 10 s, longitudinal, entity frame, no freespace. esmini 3.6.0: Twin's event
//! at 0 s, Ego's at 5.00 s (x 199.93, TTC 9.9965 s to the origin).

use crate::common::*;

#[test]
fn a_ttc_to_a_relative_position_measures_to_the_origin() {
    let run = run_fixture_on("ttc_relative_position.xosc", "straight.xodr", 6.0);
    for (action, t) in [("AbsoluteAction", 0.0), ("RelativeAction", 5.0)] {
        let start = event_time(&run, action, "start");
        assert!(start.is_some_and(|s| close(s, t, 1e-9)), "{action}: {start:?}, esmini {t}");
    }
    assert!(close(at(&run, "Ego", 5.0).x, 199.93, 1e-6));
}

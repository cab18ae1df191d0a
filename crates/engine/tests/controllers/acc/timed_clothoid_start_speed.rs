//! A timed FollowTrajectoryAction along a clothoid starts its entity at speed 0: the action's
//! Start sets the speed to the shape's current vertex speed (RMTrajectory::GetSpeed), and only
//! a polyline's vertices carry speeds — ClothoidShape (like ClothoidSplineShape and NurbsShape)
//! ::CalculatePolyLine gives its vertices times only. An ACC in override mode, under which the
//! action moves the entity at its current speed, takes that 0 as its new set speed and brakes
//! to a stop along the clothoid. Fixture `acc_timed_clothoid_start_speed.xosc` (straight road):
//! Ego's ACC (override, 20 m/s); at 2 s a clothoid of 200 m timed over 40 s (relative timing).
//! Expected values: esmini 3.6.0 on the same fixture.

use crate::common::*;

#[test]
fn a_timed_clothoid_starts_at_speed_zero_which_the_acc_brakes_to() {
    let run = run_fixture_on("acc_timed_clothoid_start_speed.xosc", "straight.xodr", 6.0);
    for (t, x, y, v) in
        [(2.01, 140.199, -1.75, 19.9), (2.5, 148.724988, -1.760509, 15.0), (3.5, 158.67444, -1.857678, 5.0), (5.0, 159.994154, -1.883229, 0.000357)]
    {
        let s = at(&run, "Ego", t);
        assert!(close(s.x, x, 1e-4) && close(s.y, y, 1e-4) && close(s.speed, v, 1e-4), "at {t}: {s:?}");
    }
}

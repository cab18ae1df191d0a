//! A speed nothing sets is derived from the motion: ScenarioEngine::prepareGroundTruth gives an
//! entity whose SPEED dirty bit no action or controller set in a step the length of its
//! displacement over the step as speed, and ScenarioEngine::step runs the default controller
//! (which sets it) only for entities with |speed| > SMALL_NUMBER. So a standing car that a
//! LaneOffsetAction moves sideways (LatLaneOffsetAction::Step sets only the LATERAL bit) takes
//! the sideways rate as its speed and drives off at it. Fixture `speed_from_displacement.xosc` on
//! `straight.xodr`, three cars standing at s = 50 from t = 0: "Step" gets a step lane offset of
//! 0.3 m at 1 s, "Cubic" a cubic one of 0.5 m at 1 s, "Held" a step one of 0.4 m at 1 s while a
//! four-second SpeedAction to 0 (started at 0.5 s) sets its speed in every step. Expected values:
//! esmini 3.6.0 on the fixture: Step 30 m/s from 1.01 s (s = 199.7 at 6 s), Cubic 0.009946 m/s
//! (its first sideways step over 0.01 s), Held stays at 0.

use crate::common::*;

#[test]
fn a_standing_car_moved_sideways_takes_the_sideways_rate_as_speed() {
    let run = run_fixture_on("speed_from_displacement.xosc", "straight.xodr", 6.0);
    let step = |t: f64| at(&run, "Step", t);
    assert!(close(step(1.0).speed, 0.0, 1e-9), "{}", step(1.0).speed);
    assert!(close(step(1.01).speed, 30.0, 1e-6) && close(step(1.01).x, 50.0, 1e-6), "{:?}", step(1.01));
    assert!(close(step(1.02).x, 50.3, 1e-6), "{:?}", step(1.02));
    assert!(close(step(6.0).x, 199.7, 1e-6) && close(step(6.0).y, -1.45, 1e-6), "{:?}", step(6.0));
    let cubic = at(&run, "Cubic", 2.0);
    assert!(close(cubic.speed, 0.009946, 1e-6) && close(cubic.x, 50.009747, 1e-5), "{cubic:?}");
    let cubic = at(&run, "Cubic", 6.0);
    assert!(close(cubic.x, 50.049529, 1e-5) && close(cubic.y, -4.75, 1e-6), "{cubic:?}");
    let held = at(&run, "Held", 6.0);
    assert!(close(held.speed, 0.0, 1e-9) && close(held.x, 50.0, 1e-9) && close(held.y, 2.15, 1e-6), "{held:?}");
}

/// At a dead end the derivation does not happen: ScenarioEngine::step tests every object for
/// the end of its road after the (possibly skipped) default move, and one whose position says
/// end of road, flagged there before, whose last velocity is zero is stopped by SetSpeed(0),
/// which marks the speed as set. Fixture `lane_offset_at_dead_end.xosc` on `straight.xodr`
/// (no links): "Stuck" drives into the road's end (s = 1000), "Back" into its start (lane 1,
/// s = 0), "Free" stands at s = 500; each gets a step lane offset of −0.5 m at 2 s. In esmini's
/// run (3.6.0) Stuck and Back stay at 0 m/s, where they are; Free takes 50 m/s and drives off.
#[test]
fn a_car_stuck_at_a_dead_end_moved_sideways_stays_stopped() {
    use crate::common::oracle::assert_fixture_matches_esmini;
    let run = assert_fixture_matches_esmini(
        "lane_offset_at_dead_end.xosc",
        4.0,
        &[
            ("Stuck", 2.02, 1000.0, -2.25, 0.0),
            ("Stuck", 3.0, 1000.0, -2.25, 0.0),
            ("Back", 2.02, 0.0, 1.25, std::f64::consts::PI),
            ("Back", 3.0, 0.0, 1.25, std::f64::consts::PI),
            ("Free", 2.02, 500.0, -2.25, 0.0),
            ("Free", 3.0, 549.0, -2.25, 0.0),
        ],
    );
    for name in ["Stuck", "Back"] {
        assert!(close(at(&run, name, 2.02).speed, 0.0, 1e-9), "{name}: {:?}", at(&run, name, 2.02));
    }
    assert!(close(at(&run, "Free", 2.02).speed, 50.0, 1e-6), "{:?}", at(&run, "Free", 2.02));
}

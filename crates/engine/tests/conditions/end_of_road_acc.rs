//! EndOfRoadCondition on an entity that an ACC controller in override mode drives:
//! ControllerACC::Step moves it (Object::MoveAlongS) after ScenarioEngine::step has checked the
//! end-of-road status of the last move, so the arrival is noted one step late. Fixture
//! `end_of_road_acc_override.xosc` (Ego reaches the end of the road at 5.00 s): esmini 3.6.0
//! starts End (duration 0.5) at 5.51 s.

use crate::common::*;

#[test]
fn the_end_of_the_road_under_an_overriding_acc_is_noted_a_step_after_the_arrival() {
    let run = run_fixture_on("end_of_road_acc_override.xosc", "straight.xodr", 7.0);
    let t = event_time(&run, "End", "start");
    assert!(t.is_some_and(|t| close(t, 5.51, 0.005)), "{t:?}");
}

/// Fixture `end_of_road_acc_creeping.xosc`: the ACC's braking speed decays towards 0 at a dead
/// end, and moves too small to change s keep the end noted (Position::MoveAlongS flags a
/// position at an unlinked road end whichever way it moved): esmini 3.6.0 starts End (duration
/// 8 s) at 8.21 s.
#[test]
fn a_car_creeping_at_a_dead_end_under_an_overriding_acc_stays_at_the_end() {
    let run = run_fixture_on("end_of_road_acc_creeping.xosc", "straight.xodr", 12.0);
    let t = event_time(&run, "End", "start");
    assert!(t.is_some_and(|t| close(t, 8.21, 0.005)), "{t:?}");
}

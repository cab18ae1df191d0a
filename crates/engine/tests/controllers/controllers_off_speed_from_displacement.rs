//! An assigned controller that is off sets no speed: ScenarioEngine::step steps only a
//! controller with some domain on (`Controller::Active`), and ScenarioEngine::prepareGroundTruth
//! gives an entity whose SPEED dirty bit nothing set in a step the length of its displacement
//! as speed. An ACC operates on the longitudinal domain only, so an ActivateControllerAction on
//! the lateral one alone leaves it off (Controller::Activate skips the domain); a
//! FollowRouteController never calls SetSpeed in its Step. A standing car a LaneOffsetAction
//! moves sideways therefore drives off at the sideways rate under either, as without a
//! controller. Fixture `controllers_off_speed_from_displacement.xosc` (straight road, four cars
//! standing, a linear 0.3 m lane offset at 1 s each): "AccLateral" (ACC activated laterally,
//! facing against its lane), "AccOff" (ACC never activated), "Router" (FollowRoute activated
//! laterally), "AccOn" (ACC activated longitudinally: it drives to its 15 m/s set speed).
//! Expected values: esmini 3.6.0 on the same fixture.

use crate::common::*;

#[test]
fn a_standing_car_whose_controller_is_off_takes_its_sideways_rate_as_speed() {
    let run = run_fixture_on("controllers_off_speed_from_displacement.xosc", "straight.xodr", 4.0);
    for (name, x0, y) in [("AccLateral", 100.0, 1.45), ("AccOff", 200.0, -2.05), ("Router", 100.0, -5.55)] {
        let a = at(&run, name, 1.5);
        assert!(close(a.speed, 0.316228, 1e-6) && close(a.x, x0 + 0.151789, 1e-5), "{name}: {a:?}");
        let b = at(&run, name, 4.0);
        assert!(close(b.x, x0 + 0.942359, 1e-5) && close(b.y, y, 1e-6) && close(b.speed, 0.316228, 1e-6), "{name}: {b:?}");
    }
    let on = at(&run, "AccOn", 4.0);
    assert!(close(on.x, 343.937143, 1e-4) && close(on.speed, 15.0, 1e-6), "{on:?}");
}

/// A standing car placed by a WorldPosition off its lane centre: the hair by which esmini's
/// XYZ2TrackPos puts it further out (cos(1e-6)) moves it 3.5e-12 m in the first step of a
/// LaneOffsetAction, a derived speed of 3.5e-10 m/s that ScenarioEngine::step still counts as
/// standing (|speed| <= SMALL_NUMBER, 1e-6): the sideways rate becomes its speed as without the
/// hair. Fixture `world_placed_standing_lane_offset.xosc`; expected values from esmini 3.6.0.
#[test]
fn a_hair_of_motion_leaves_a_standing_car_standing_for_the_default_controller() {
    let run = run_fixture_on("world_placed_standing_lane_offset.xosc", "straight.xodr", 5.0);
    let a = at(&run, "Car", 1.5);
    assert!(close(a.x, 100.183303, 1e-5) && close(a.y, -6.812878, 1e-5) && close(a.speed, 0.381881, 1e-5), "{a:?}");
    let b = at(&run, "Car", 4.0);
    assert!(close(b.x, 101.138006, 1e-5) && close(b.y, -5.858175, 1e-5) && close(b.speed, 0.381881, 1e-5), "{b:?}");
}

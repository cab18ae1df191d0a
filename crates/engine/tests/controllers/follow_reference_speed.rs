//! FollowReferenceController measures from its entity, not from its own vehicle model: esmini's
//! ControllerFollowReference::Step reads `object_->GetSpeed()` for the speed spring and the
//! Stanley steering, and the controller forces override mode on both domains.
//!
//! Fixture `follow_reference_speed_under_override.xosc` on straight.xodr: Ego and Ego2 follow a
//! lead 20 m ahead at 10 m/s, each from 8 m/s.
//! - Each starts with an init SpeedAction of rate 2 m/s² that the init's activation ends in its
//!   first step (LongSpeedAction::Step under override), so the speed is the spring's from then.
//! - At t = 2 a SpeedProfileAction on Ego (LongSpeedProfileAction::Step checks no override) sets
//!   Ego's speed every step, and the spring reacts to that speed, not to its model's: it
//!   sees Ego slower than the lead, pulls, and Ego runs away ahead (6 m beyond Ego2 at t = 4).
//! - At t = 2 a SpeedAction on Ego2 ends at once (LongSpeedAction::Start): Ego2 keeps following.
//!
//! Numbers from esmini 3.6.0's run.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "follow_reference_speed_under_override.xosc";

#[test]
fn an_action_that_sets_the_speed_under_override_moves_the_controllers_input() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    let (ego, ego2) = (at(&run, "Ego", 4.0), at(&run, "Ego2", 4.0));
    assert!(ego.x > ego2.x + 5.0, "the spring pulls on the profile's speed: {ego:?} {ego2:?}");
    assert_esmini_pose_at(&run, "Ego", 4.0, 159.587037, -1.75, 0.0);
    assert_esmini_pose_at(&run, "Ego2", 4.0, 153.242823, -5.25, 0.0);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

/// Fixture `follow_reference_off_a_dead_end.xosc`: the controller's placement locates the
/// entity afresh (Position::SetInertiaPos), end-of-road status included, so an
/// EndOfRoadCondition on a FollowReference entity that drives past a dead end fires: esmini
/// starts Marker at 4.38 s, when Ego is 0.2 m past the road's end.
#[test]
fn a_follower_driven_past_a_dead_end_is_at_the_end_of_the_road() {
    const OFF: &str = "follow_reference_off_a_dead_end.xosc";
    let run = run_fixture_scenario(OFF, 20.0);
    let started = event_time(&run, "End", "start");
    assert!(started.is_some_and(|t| (t - 4.38).abs() < 1e-6), "Marker's event starts at {started:?}");
    assert!(at(&run, "Marker", 4.39).speed > 0.5);
    assert_matches_esmini(OFF, &run, 1e-3);
}

/// Fixture `follow_reference_banked_frame0.xosc`: a FollowReferenceController is stepped in
/// frame 0 too (ScenarioEngine::step steps every active controller, dt 0). Its
/// Position::SetInertiaPos moves nothing but takes the entity's heading as absolute, and on
/// a banked road EvaluateHPR turns it by the road's rotation again: esmini 3.6.0 reports Ego's
/// heading at time 0 as 0.022681 rad, where the lane position alone gives about 0.015.
#[test]
fn a_follower_on_a_banked_road_is_placed_in_frame_0_too() {
    const BANKED: &str = "follow_reference_banked_frame0.xosc";
    let run = run_fixture_scenario(BANKED, 20.0);
    assert!(close(at(&run, "Ego", 0.0).h, 0.022681, 1e-6), "{:?}", at(&run, "Ego", 0.0));
    assert_esmini_pose_at(&run, "Ego", 2.0, 132.498381, -0.674289, 0.029183);
    assert_matches_esmini(BANKED, &run, 1e-3);
}

//! FollowReferenceController's ties, as ControllerFollowReference::Step meets them.
//!
//! A reference facing exactly the other way: the heading difference is wrapped by esmini's
//! GetAngleInIntervalMinusPIPlusPI, which keeps +π (fmod, then only values beyond ±π move),
//! so the heading term of the Stanley steering turns left; wrapping into [−π, π) gives −π and
//! a turn to the right. Fixture `follow_reference_facing_away.xosc` on straight.xodr: the Ego
//! at 5 m/s in lane −1, the reference 60 m ahead in lane 1 at 10 m/s the other way.
//!
//! A follower reversing on the reference's line: the cross-track error is exactly zero and
//! the speed term negative, so atan2 gives ±π by the sign of that zero; esmini's
//! DistanceFromPointToLine2DWithAngle (x·sin − y·cos) gives +0. Fixture
//! `follow_reference_reversing_on_line.xosc`: the reference 70 m behind in the same lane.
//!
//! The same with the reference placed by a WorldPosition on the lane centre: esmini's
//! Position::XYZ2TrackPos divides a world point's lateral offset by cos(AVOID_ZERO(0)) =
//! cos(1e-6), so the reference drives 5e-13 of its t further right, the Ego is a hair left of
//! its line and the turn goes the other way. Fixture
//! `follow_reference_reversing_world_placed.xosc`.
//!
//! The same with the Ego placed at a lane centre that does not add up exactly in binary:
//! esmini's LaneSection::GetCenterOffset takes the summed widths out to the lane's outer border
//! less half its width, 10.4 − 1.95 = 8.450000000000001 for lane 3 of
//! straight_odd_widths.xodr (widths 2.6, 3.9, 3.9), while the reference, placed by a
//! RoadPosition at t = 8.45, sits on 8.45: the Ego is a hair left of the reference's line and,
//! reversing, turns its wheels right. Fixture `follow_reference_reversing_lane_centre.xosc`.
//!
//! Numbers from esmini 3.6.0's runs.

use crate::common::oracle::{assert_esmini_pose_at, assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

const FIXTURE: &str = "follow_reference_facing_away.xosc";
const REVERSING: &str = "follow_reference_reversing_on_line.xosc";
const WORLD_PLACED: &str = "follow_reference_reversing_world_placed.xosc";
const LANE_CENTRE: &str = "follow_reference_reversing_lane_centre.xosc";

#[test]
fn a_reference_facing_the_other_way_turns_the_follower_left() {
    let run = run_fixture_scenario(FIXTURE, 20.0);
    // Left from the first steps: heading up from 0, y up from the lane centre.
    let first = at(&run, "Ego", 0.1);
    assert!(first.h > 0.2 && first.h < 0.3 && first.y > -1.75, "{first:?}");
    assert_esmini_pose_at(&run, "Ego", 0.1, 100.648667, -1.507444, 0.230832);
    assert_esmini_pose_at(&run, "Ego", 1.0, 98.417928, 4.440928, 2.965832);
    assert_esmini_pose_at(&run, "Ego", 8.0, 76.862190, 1.915216, 3.173443);
    assert_matches_esmini(FIXTURE, &run, 1e-3);
}

#[test]
fn reversing_on_the_references_line_turns_the_wheels_left() {
    let run = run_fixture_scenario(REVERSING, 20.0);
    // Backwards with the wheels turned left: the rear swings right of the lane centre.
    let early = at(&run, "Ego", 0.5);
    assert!(early.speed < 0.0 && early.y < -1.75, "{early:?}");
    assert_esmini_pose_at(&run, "Ego", 0.5, 93.107972, -3.309184, 0.652394);
    assert_esmini_pose_at(&run, "Ego", 1.0, 88.106302, -0.148681, 4.947992);
    assert_esmini_pose_at(&run, "Ego", 5.0, 84.999724, 2.672464, 0.229354);
    assert_matches_esmini(REVERSING, &run, 1e-3);
}

#[test]
fn a_reference_placed_in_the_world_lies_a_hair_right_of_its_lane_centre() {
    let run = run_fixture_scenario(WORLD_PLACED, 20.0);
    // Forward for a moment, steering right by a hair (the heading wraps just below 2π), then
    // backwards with the wheels turned right: the rear swings left of the lane centre.
    let first = at(&run, "Ego", 0.02);
    assert!(first.h > 6.0 && first.speed > 0.0, "{first:?}");
    let early = at(&run, "Ego", 0.5);
    assert!(early.speed < 0.0 && early.y > -1.75, "{early:?}");
    assert_esmini_pose_at(&run, "Ego", 0.5, 93.107972, -0.190816, 5.630792);
    assert_esmini_pose_at(&run, "Ego", 1.0, 88.106302, -3.351319, 1.335193);
    assert_esmini_pose_at(&run, "Ego", 5.0, 84.999724, -6.172464, 6.053831);
    assert_matches_esmini(WORLD_PLACED, &run, 1e-3);
}

#[test]
fn a_lane_centre_summed_as_esmini_sums_it_lies_a_hair_left_of_the_reference() {
    let run = run_fixture_scenario(LANE_CENTRE, 20.0);
    // Backwards with the wheels turned right: the heading goes up from 0 and the rear swings
    // left of the lane centre (y = 8.45).
    let early = at(&run, "Ego", 0.1);
    assert!(early.speed < 0.0 && early.y > 8.45 && early.h > 0.0 && early.h < 1.0, "{early:?}");
    assert_esmini_pose_at(&run, "Ego", 0.1, 99.715095, 8.520089, 0.112615);
    assert_esmini_pose_at(&run, "Ego", 0.5, 93.107972, 10.009184, 5.630792);
    assert_esmini_pose_at(&run, "Ego", 1.0, 88.106302, 6.848681, 1.335193);
    assert_esmini_pose_at(&run, "Ego", 5.0, 84.999724, 4.027536, 6.053831);
    assert_matches_esmini(LANE_CENTRE, &run, 1e-3);
}

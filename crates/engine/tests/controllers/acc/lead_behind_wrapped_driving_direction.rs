//! Whether a car on the next road is ahead of an ACC car that faces exactly against its lane:
//! RoadPath::Calculate turns the path's distance negative when GetHRelativeDrivingDirection,
//! the angle difference between the heading the position holds and Position::GetDrivingDirection,
//! lies past π/2. GetDrivingDirection turns the road heading by π with GetAngleSum, which wraps
//! into [0, 2π): on a road heading π a lane-1 car facing along s gets a driving direction of 0
//! and a difference of +π, so the car ahead is behind it and is no lead. Found by helpers on
//! s60060_00717's family (s58058_00846, s58058_00236), where the engine, turning the heading
//! unwrapped, got −π and braked for the car.
//!
//! Fixture `acc_facing_against_wrapped_driving_direction.xosc` on westward.xodr (two roads in a
//! line heading π): Car1 (ACC, additive) in lane 1 of road 1 facing along s at 15 m/s, Car0
//! parked 60 m ahead on road 2. esmini 3.6.0 holds 15 m/s to the road's end.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_car_facing_against_its_lane_on_a_road_heading_pi_sees_no_lead_ahead() {
    assert_fixture_matches_esmini(
        "acc_facing_against_wrapped_driving_direction.xosc",
        2.0,
        &[("Car1", 1.0, 115.0, -1.75, std::f64::consts::PI), ("Car1", 1.9, 101.5, -1.75, std::f64::consts::PI)],
    );
}

/// The same car on a road whose heading is given as 2π (its geometry's `hdg`, which esmini's
/// road heading keeps unwrapped): the driving direction wraps to π and the car's own heading,
/// 0, differs from it by −π, so the car ahead on the next road is a lead and the ACC brakes.
/// Composing the heading with the road's first (as SynchronizeAction's master does) gave 2π and
/// +π, and no lead. Fixture `acc_facing_against_lane_on_heading_two_pi.xosc` on
/// heading_two_pi.xodr; found on s59059_00475.
#[test]
fn on_a_road_heading_two_pi_the_car_ahead_is_a_lead() {
    assert_fixture_matches_esmini(
        "acc_facing_against_lane_on_heading_two_pi.xosc",
        2.0,
        &[("Car1", 1.0, -15.0, 1.75, 0.0), ("Car1", 2.0, -0.669921, 1.75, 0.0)],
    );
}

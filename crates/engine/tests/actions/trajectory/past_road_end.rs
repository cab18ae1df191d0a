//! A trajectory that carries a car past the dead end of a road: esmini 3.6's ScenarioEngine::step
//! stops an entity whose position lies past the end of the road (Position::XYZ2TrackPos sets
//! POS_STATUS_END_OF_ROAD when the closest road point is outside every road), that is already
//! flagged there and did not move in the last step — whoever moved it. A clothoid spline whose
//! length ends in a fraction of a metre holds the car at its last vertex for some steps (the
//! one-metre polyline), so the car is stopped there, the trajectory never reaches its end and
//! the car stays past the road's end; one that ends moving hands the car to the default
//! controller, which puts it back at the road's end.
//!
//! Fixture `trajectory_past_road_end.xosc` on straight.xodr (1 km, no successor): two untimed
//! clothoid splines from 960 m, 50.6 m and 50 m long, at 10 m/s. The numbers are esmini 3.6.0's
//! run; where esmini runs here the whole run is compared.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn a_car_standing_past_a_dead_end_on_its_trajectory_is_stopped_there() {
    let run = assert_fixture_matches_esmini(
        "trajectory_past_road_end.xosc",
        20.0,
        &[
            ("Fraction", 6.0, 1010.436809, -2.172786, 6.258043),
            // Stopped where the trajectory held it, past the road's end.
            ("Fraction", 8.0, 1010.596761, -2.176707, 6.257885),
            // Ended moving: back at the road's end.
            ("Whole", 8.0, 1000.0, -5.666648, 6.258185),
        ],
    );
    let last_speed = run.trace.entities.iter().find(|e| e.name == "Fraction").and_then(|e| e.samples.iter().rev().flatten().next()).map(|s| s.speed);
    assert_eq!(last_speed, Some(0.0));
}

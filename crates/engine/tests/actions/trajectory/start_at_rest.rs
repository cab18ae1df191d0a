//! A timed clothoid spline, NURBS or clothoid starts the entity at rest: esmini 3.6's
//! FollowTrajectoryAction::Start sets the speed to RMTrajectory::GetSpeed, the speed of the
//! shape's one-metre polyline, and only a polyline's vertices get one (ClothoidShape,
//! ClothoidSplineShape and NurbsShape::CalculatePolyLine leave TrajVertex::speed at 0). So a
//! first step already past the last stamp (a relative offset beyond the end) leaves the entity
//! standing at the path's end with nothing to run on, and an ACC in override mode, which holds
//! the speed, takes the drop to 0 as its new set speed and brakes to a stop along the path.
//!
//! Fixture `trajectory_start_at_rest.xosc` on straight.xodr: a 3 s spline and a 2 s NURBS with
//! relative offsets past their ends, and a 30 s clothoid timed absolutely under an ACC, all
//! started at 1 s at 10 m/s. The numbers are esmini 3.6.0's run; where esmini runs here the
//! whole run is compared.

use crate::common::oracle::assert_fixture_matches_esmini;

#[test]
fn timed_clothoids_and_nurbs_start_the_entity_at_rest() {
    assert_fixture_matches_esmini(
        "trajectory_start_at_rest.xosc",
        20.0,
        &[
            // At the path's end at once, and standing there.
            ("SplinePast", 1.02, 49.93257, -0.252409, 0.15),
            ("NurbsPast", 1.02, 49.99997, -2.000006, 0.213265),
            ("NurbsPast", 4.0, 49.99997, -2.000006, 0.213265),
            // The ACC brakes to the new set speed, 0.
            ("AccClothoid", 2.0, 116.928152, -1.739015, 0.004771),
            ("AccClothoid", 4.0, 117.232773, -1.737388, 0.005231),
        ],
    );
}

//! Table I of the paper, row by row, and which CommonRoad element each type may become.

use crate::common::*;
use commonroad::{DynamicObstacleType as D, EnvironmentObstacleType as E, StaticObstacleType as S};
use convert::{cr_type, CrType};
use openscenario::{MiscObjectCategory as M, PedestrianCategory as P, VehicleCategory as V};

#[test]
fn vehicles() {
    let rows = [
        (V::Car, CrType::Car),
        (V::Van, CrType::Car),
        (V::Truck, CrType::Truck),
        (V::Trailer, CrType::Truck),
        (V::Semitrailer, CrType::Truck),
        (V::Bus, CrType::Bus),
        (V::Motorbike, CrType::Motorcycle),
        (V::Bicycle, CrType::Bicycle),
        (V::Train, CrType::Train),
        (V::Tram, CrType::Train),
    ];
    for (cat, want) in rows {
        let e = vehicle("v", cat, bbox(1.0, 0.0, 4.0, 2.0));
        assert_eq!(cr_type(&e.object), want, "{cat:?}");
    }
}

#[test]
fn pedestrians_of_any_category() {
    for cat in [P::Pedestrian, P::Wheelchair, P::Animal] {
        let e = pedestrian("p", cat, bbox(0.0, 0.0, 0.5, 0.5));
        assert_eq!(cr_type(&e.object), CrType::Pedestrian, "{cat:?}");
    }
}

#[test]
fn misc_objects() {
    let rows = [
        (M::Building, CrType::Building),
        (M::TrafficIsland, CrType::MedianStrip),
        (M::StreetLamp, CrType::Pillar),
        (M::Pole, CrType::RoadBoundary),
        (M::Barrier, CrType::RoadBoundary),
        (M::Railing, CrType::RoadBoundary),
        (M::SoundBarrier, CrType::RoadBoundary),
        (M::Patch, CrType::ConstructionZone),
        // anything else
        (M::None, CrType::Unknown),
        (M::Obstacle, CrType::Unknown),
        (M::Tree, CrType::Unknown),
        (M::Vegetation, CrType::Unknown),
        (M::ParkingSpace, CrType::Unknown),
        (M::Crosswalk, CrType::Unknown),
        (M::Gantry, CrType::Unknown),
        (M::Wind, CrType::Unknown),
        (M::RoadMark, CrType::Unknown),
    ];
    for (cat, want) in rows {
        let e = misc("m", cat, bbox(0.0, 0.0, 1.0, 1.0));
        assert_eq!(cr_type(&e.object), want, "{cat:?}");
    }
}

#[test]
fn external_objects_are_unknown() {
    let e = openscenario::EntityObject::External { name: "x".into() };
    assert_eq!(cr_type(&e), CrType::Unknown);
}

#[test]
fn element_kinds_follow_the_xsd() {
    // staticObstacle: unknown, parkedVehicle, constructionZone, roadBoundary
    assert_eq!(CrType::RoadBoundary.static_type(), Some(S::RoadBoundary));
    assert_eq!(CrType::ConstructionZone.static_type(), Some(S::ConstructionZone));
    assert_eq!(CrType::Unknown.static_type(), Some(S::Unknown));
    assert_eq!(CrType::Car.static_type(), None);
    assert_eq!(CrType::Building.static_type(), None);
    // environmentObstacle: building, pillar, median_strip
    assert_eq!(CrType::Building.environment(), Some(E::Building));
    assert_eq!(CrType::Pillar.environment(), Some(E::Pillar));
    assert_eq!(CrType::MedianStrip.environment(), Some(E::MedianStrip));
    assert_eq!(CrType::RoadBoundary.environment(), None);
    // dynamicObstacle: road users and unknown
    assert_eq!(CrType::Car.dynamic(), Some(D::Car));
    assert_eq!(CrType::Truck.dynamic(), Some(D::Truck));
    assert_eq!(CrType::Bus.dynamic(), Some(D::Bus));
    assert_eq!(CrType::Motorcycle.dynamic(), Some(D::Motorcycle));
    assert_eq!(CrType::Bicycle.dynamic(), Some(D::Bicycle));
    assert_eq!(CrType::Train.dynamic(), Some(D::Train));
    assert_eq!(CrType::Pedestrian.dynamic(), Some(D::Pedestrian));
    assert_eq!(CrType::Unknown.dynamic(), Some(D::Unknown));
    assert_eq!(CrType::Building.dynamic(), None);
    assert_eq!(CrType::RoadBoundary.dynamic(), None);
}

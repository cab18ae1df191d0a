//! Table I of the paper: which CommonRoad obstacle type an OpenSCENARIO entity becomes, and
//! which CommonRoad element (dynamic, static, environment obstacle) may carry that type.

use commonroad::{DynamicObstacleType, EnvironmentObstacleType, StaticObstacleType};
use openscenario::{EntityObject, MiscObjectCategory, VehicleCategory};

/// The CommonRoad types of Table I.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum CrType {
    Car,
    Truck,
    Bus,
    Motorcycle,
    Bicycle,
    Train,
    Pedestrian,
    Building,
    MedianStrip,
    Pillar,
    RoadBoundary,
    ConstructionZone,
    Unknown,
}

/// Table I.
pub fn cr_type(object: &EntityObject) -> CrType {
    use MiscObjectCategory as M;
    use VehicleCategory as V;
    match object {
        EntityObject::Vehicle(v) => match v.category {
            V::Car | V::Van => CrType::Car,
            V::Truck | V::Trailer | V::Semitrailer => CrType::Truck,
            V::Bus => CrType::Bus,
            V::Motorbike => CrType::Motorcycle,
            V::Bicycle => CrType::Bicycle,
            V::Train | V::Tram => CrType::Train,
        },
        EntityObject::Pedestrian(_) => CrType::Pedestrian,
        EntityObject::MiscObject(m) => match m.category {
            M::Building => CrType::Building,
            M::TrafficIsland => CrType::MedianStrip,
            M::StreetLamp => CrType::Pillar,
            M::Pole | M::Barrier | M::Railing | M::SoundBarrier => CrType::RoadBoundary,
            M::Patch => CrType::ConstructionZone,
            _ => CrType::Unknown,
        },
        EntityObject::External { .. } => CrType::Unknown,
    }
}

impl CrType {
    /// The `dynamicObstacle` type, or `None` when the XSD does not allow this type there.
    pub fn dynamic(self) -> Option<DynamicObstacleType> {
        Some(match self {
            CrType::Car => DynamicObstacleType::Car,
            CrType::Truck => DynamicObstacleType::Truck,
            CrType::Bus => DynamicObstacleType::Bus,
            CrType::Motorcycle => DynamicObstacleType::Motorcycle,
            CrType::Bicycle => DynamicObstacleType::Bicycle,
            CrType::Train => DynamicObstacleType::Train,
            CrType::Pedestrian => DynamicObstacleType::Pedestrian,
            CrType::Unknown => DynamicObstacleType::Unknown,
            _ => return None,
        })
    }

    /// The `staticObstacle` type, or `None` when the XSD does not allow this type there.
    pub fn static_type(self) -> Option<StaticObstacleType> {
        Some(match self {
            CrType::RoadBoundary => StaticObstacleType::RoadBoundary,
            CrType::ConstructionZone => StaticObstacleType::ConstructionZone,
            CrType::Unknown => StaticObstacleType::Unknown,
            _ => return None,
        })
    }

    /// The `environmentObstacle` type, or `None` when the XSD does not allow this type there.
    pub fn environment(self) -> Option<EnvironmentObstacleType> {
        Some(match self {
            CrType::Building => EnvironmentObstacleType::Building,
            CrType::Pillar => EnvironmentObstacleType::Pillar,
            CrType::MedianStrip => EnvironmentObstacleType::MedianStrip,
            _ => return None,
        })
    }

    /// Vehicles and pedestrians are dynamic obstacles even when standing still (2020a has
    /// no static car); only miscellaneous objects may become static or environment obstacles.
    pub fn always_dynamic(object: &EntityObject) -> bool {
        !matches!(object, EntityObject::MiscObject(_))
    }
}

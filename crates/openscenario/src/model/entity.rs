//! Entities: vehicles, pedestrians, miscellaneous objects, their controllers, selections.

use super::Origin;
use crate::params::ParameterDeclaration;
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Entity {
    pub name: String,
    pub object: EntityObject,
    /// ObjectController(s) (1.3 allows several).
    pub controllers: Vec<Controller>,
    pub origin: Origin,
}

// Few entities per scenario: boxing the large Vehicle would only complicate matching.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum EntityObject {
    Vehicle(Vehicle),
    Pedestrian(Pedestrian),
    MiscObject(MiscObject),
    /// ExternalObjectReference: an object defined outside the scenario.
    External {
        name: String,
    },
}

impl EntityObject {
    pub fn bounding_box(&self) -> Option<&BoundingBox> {
        match self {
            EntityObject::Vehicle(v) => Some(&v.bounding_box),
            EntityObject::Pedestrian(p) => Some(&p.bounding_box),
            EntityObject::MiscObject(m) => Some(&m.bounding_box),
            EntityObject::External { .. } => None,
        }
    }
}

crate::xml_enum! {
    VehicleCategory {
        Car = "car", Van = "van", Truck = "truck", Trailer = "trailer", Semitrailer = "semitrailer",
        Bus = "bus", Motorbike = "motorbike", Bicycle = "bicycle", Train = "train", Tram = "tram",
    }
}
crate::xml_enum! {
    PedestrianCategory { Pedestrian = "pedestrian", Wheelchair = "wheelchair", Animal = "animal" }
}
crate::xml_enum! {
    MiscObjectCategory {
        None = "none", Obstacle = "obstacle", Pole = "pole", Tree = "tree", Vegetation = "vegetation",
        Barrier = "barrier", Building = "building", ParkingSpace = "parkingSpace", Patch = "patch",
        Railing = "railing", TrafficIsland = "trafficIsland", Crosswalk = "crosswalk",
        StreetLamp = "streetLamp", Gantry = "gantry", SoundBarrier = "soundBarrier", Wind = "wind",
        RoadMark = "roadMark",
    }
}
crate::xml_enum! {
    Role {
        None = "none", Ambulance = "ambulance", Civil = "civil", Fire = "fire", Military = "military",
        Police = "police", PublicTransport = "publicTransport", RoadAssistance = "roadAssistance",
    }
}
crate::xml_enum! {
    ObjectType { Pedestrian = "pedestrian", Vehicle = "vehicle", MiscellaneousObject = "miscellaneous", External = "external" }
}
crate::xml_enum! {
    ControllerType {
        Lateral = "lateral", Longitudinal = "longitudinal", Lighting = "lighting", Animation = "animation",
        Movement = "movement", Appearance = "appearance", All = "all",
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Vec3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BoundingBox {
    /// Centre of the box relative to the entity's reference point (vehicle: rear axle).
    pub center: Vec3,
    pub width: f64,
    pub length: f64,
    pub height: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Vehicle {
    pub name: String,
    pub category: VehicleCategory,
    pub role: Option<Role>,
    pub mass: Option<f64>,
    pub model3d: Option<String>,
    pub parameters: Vec<ParameterDeclaration>,
    pub bounding_box: BoundingBox,
    pub performance: Performance,
    pub axles: Axles,
    pub properties: Properties,
    pub trailer_hitch: Option<f64>,
    pub trailer_coupler: Option<f64>,
    pub trailer: Option<Trailer>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Trailer {
    /// An inline trailer entity.
    Entity(Box<Entity>),
    /// TrailerRef: the name of another entity.
    Ref(String),
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Performance {
    pub max_speed: f64,
    pub max_acceleration: f64,
    pub max_deceleration: f64,
    pub max_acceleration_rate: Option<f64>,
    pub max_deceleration_rate: Option<f64>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Axle {
    pub max_steering: f64,
    pub wheel_diameter: f64,
    pub track_width: f64,
    pub position_x: f64,
    pub position_z: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Axles {
    pub front: Option<Axle>,
    pub rear: Axle,
    pub additional: Vec<Axle>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Pedestrian {
    pub name: String,
    pub category: PedestrianCategory,
    pub role: Option<Role>,
    pub mass: f64,
    pub model3d: Option<String>,
    pub parameters: Vec<ParameterDeclaration>,
    pub bounding_box: BoundingBox,
    pub properties: Properties,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MiscObject {
    pub name: String,
    pub category: MiscObjectCategory,
    pub mass: f64,
    pub model3d: Option<String>,
    pub parameters: Vec<ParameterDeclaration>,
    pub bounding_box: BoundingBox,
    pub properties: Properties,
}

/// Name/value properties and file references.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Properties {
    pub properties: Vec<(String, String)>,
    pub files: Vec<String>,
}

impl Properties {
    pub fn get(&self, name: &str) -> Option<&str> {
        self.properties.iter().rev().find(|(n, _)| n == name).map(|(_, v)| v.as_str())
    }
}

/// A controller (from ObjectController, AssignControllerAction, or a catalog).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Controller {
    pub name: String,
    pub controller_type: Option<ControllerType>,
    pub parameters: Vec<ParameterDeclaration>,
    pub properties: Properties,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EntitySelection {
    pub name: String,
    pub members: Vec<SelectionMember>,
    pub origin: Origin,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum SelectionMember {
    Entity(String),
    ByType(ObjectType),
}

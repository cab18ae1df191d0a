//! A moving object of one frame, as esmini's `OSIReporter::UpdateOSIMovingObject` fills it: its
//! id, OSI type and vehicle classification (esmini's mapping of categories and roles), the base
//! — bounding-box dimensions, the box centre in the OpenDRIVE frame (the reference point moved
//! by the box centre turned by heading and pitch, `Position::SetOsiXYZ`), orientation,
//! velocity, acceleration, yaw rate and yaw acceleration in the world frame (`kinematics`) —,
//! the lane it is assigned to, the box centre's distance to the rear and front axle, and the
//! source reference naming the entity. Not filled: wheel data, light states, colour, 3D model.

use openscenario::{EntityObject, MiscObjectCategory, PedestrianCategory, Role, VehicleCategory};

use crate::kinematics::Motion;
use crate::osi3::moving_object::vehicle_classification::{Role as OsiRole, Type as VehicleType};
use crate::osi3::moving_object::{Type as MovingType, VehicleAttributes, VehicleClassification};
use crate::osi3::stationary_object::classification::Type as StationaryType;
use crate::osi3::{
    stationary_object, BaseMoving, BaseStationary, Dimension3d, ExternalReference, Identifier, MovingObject, Orientation3d, StationaryObject, Vector3d,
};

/// esmini's `SOURCE_REF_TYPE_OSC`.
const SOURCE_OSC: &str = "net.asam.openscenario";

pub fn id(v: u64) -> Option<Identifier> {
    Some(Identifier { value: Some(v) })
}

pub fn vec3(x: f64, y: f64, z: f64) -> Option<Vector3d> {
    Some(Vector3d { x: Some(x), y: Some(y), z: Some(z) })
}

pub fn orientation(roll: f64, pitch: f64, yaw: f64) -> Option<Orientation3d> {
    Some(Orientation3d { roll: Some(roll), pitch: Some(pitch), yaw: Some(yaw) })
}

fn dimension(b: &openscenario::BoundingBox) -> Option<Dimension3d> {
    Some(Dimension3d { length: Some(b.length), width: Some(b.width), height: Some(b.height) })
}

fn vehicle_type(c: VehicleCategory) -> VehicleType {
    match c {
        VehicleCategory::Car => VehicleType::MediumCar,
        // esmini reports a tram as a delivery van
        VehicleCategory::Van | VehicleCategory::Tram => VehicleType::DeliveryVan,
        VehicleCategory::Truck => VehicleType::HeavyTruck,
        VehicleCategory::Semitrailer => VehicleType::Semitrailer,
        VehicleCategory::Trailer => VehicleType::Trailer,
        VehicleCategory::Bus => VehicleType::Bus,
        VehicleCategory::Motorbike => VehicleType::Motorbike,
        VehicleCategory::Bicycle => VehicleType::Bicycle,
        VehicleCategory::Train => VehicleType::Train,
    }
}

fn role(r: Option<Role>) -> OsiRole {
    match r {
        None | Some(Role::None) => OsiRole::Unknown,
        Some(Role::Ambulance) => OsiRole::Ambulance,
        Some(Role::Civil) => OsiRole::Civil,
        Some(Role::Fire) => OsiRole::Fire,
        Some(Role::Military) => OsiRole::Military,
        Some(Role::Police) => OsiRole::Police,
        Some(Role::PublicTransport) => OsiRole::PublicTransport,
        Some(Role::RoadAssistance) => OsiRole::RoadAssistance,
    }
}

/// The moving object of entity `name` (a vehicle or pedestrian `model`, esmini object index
/// `index`, OSI id `osi_id`) in `motion`, assigned to lane `lane_id`.
pub fn moving_object(name: &str, index: usize, osi_id: u64, model: &EntityObject, motion: &Motion, lane_id: u64) -> Option<MovingObject> {
    let (bbox, kind, classification, entity_type) = match model {
        EntityObject::Vehicle(v) => (
            &v.bounding_box,
            MovingType::Vehicle,
            Some(VehicleClassification { r#type: Some(vehicle_type(v.category) as i32), role: Some(role(v.role) as i32) }),
            "Vehicle",
        ),
        EntityObject::Pedestrian(p) => {
            let kind = match p.category {
                PedestrianCategory::Pedestrian => MovingType::Pedestrian,
                PedestrianCategory::Wheelchair => MovingType::Other,
                PedestrianCategory::Animal => MovingType::Animal,
            };
            (&p.bounding_box, kind, None, "Pedestrian")
        }
        EntityObject::MiscObject(_) | EntityObject::External { .. } => return None,
    };
    let c = bbox.center;
    let (cx, cy, cz) = motion.rotate(c.x, c.y, c.z);
    let attributes = match model {
        EntityObject::Vehicle(v) => Some(VehicleAttributes {
            bbcenter_to_rear: vec3(-c.x, -c.y, v.axles.rear.position_z - c.z),
            bbcenter_to_front: v.axles.front.map(|f| vec3(f.position_x - c.x, -c.y, f.position_z - c.z)).unwrap_or_default(),
        }),
        _ => None,
    };
    Some(MovingObject {
        id: id(osi_id),
        base: Some(BaseMoving {
            dimension: dimension(bbox),
            position: vec3(motion.x + cx, motion.y + cy, motion.z + cz),
            orientation: orientation(0.0, motion.pitch, motion.yaw),
            velocity: vec3(motion.velocity.0, motion.velocity.1, motion.velocity.2),
            acceleration: vec3(motion.acceleration.0, motion.acceleration.1, motion.acceleration.2),
            orientation_rate: orientation(0.0, 0.0, motion.yaw_rate),
            orientation_acceleration: orientation(0.0, 0.0, motion.yaw_acceleration),
        }),
        r#type: Some(kind as i32),
        assigned_lane_id: id(lane_id).into_iter().collect(),
        vehicle_attributes: attributes,
        vehicle_classification: classification,
        source_reference: vec![ExternalReference {
            r#type: Some(SOURCE_OSC.into()),
            identifier: vec![format!("entity_id:{index}"), format!("entity_type:{entity_type}"), format!("entity_name:{name}")],
        }],
    })
}

fn stationary_type(c: MiscObjectCategory) -> StationaryType {
    match c {
        MiscObjectCategory::None => StationaryType::Unknown,
        MiscObjectCategory::Pole => StationaryType::Pole,
        MiscObjectCategory::Tree => StationaryType::Tree,
        MiscObjectCategory::Vegetation => StationaryType::Vegetation,
        MiscObjectCategory::Barrier => StationaryType::Barrier,
        MiscObjectCategory::Building => StationaryType::Building,
        _ => StationaryType::Other,
    }
}

/// The stationary object of MiscObject entity `name` (OSI id `osi_id`) where `motion` puts it
/// (`OSIReporter::UpdateOSIStationaryObject`: the box centre moved along the heading only, its
/// height at half the box's height above the reference point).
pub fn stationary_object(name: &str, osi_id: u64, model: &EntityObject, motion: &Motion) -> Option<StationaryObject> {
    let EntityObject::MiscObject(m) = model else { return None };
    let b = &m.bounding_box;
    let (sin, cos) = motion.yaw.sin_cos();
    Some(StationaryObject {
        id: id(osi_id),
        base: Some(BaseStationary {
            dimension: dimension(b),
            position: vec3(motion.x + b.center.x * cos, motion.y + b.center.x * sin, motion.z + b.height / 2.0),
            orientation: orientation(0.0, motion.pitch, motion.yaw),
        }),
        classification: Some(stationary_object::Classification { r#type: Some(stationary_type(m.category) as i32) }),
        source_reference: vec![ExternalReference {
            r#type: Some(SOURCE_OSC.into()),
            identifier: vec!["object_type:MiscObject".into(), format!("object_name:{name}")],
        }],
    })
}

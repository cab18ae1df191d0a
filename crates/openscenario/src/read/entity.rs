//! Entities, their objects (inline or from catalogs) and controllers.

use super::Reader;
use crate::attr::Cx;
use crate::catalog::CatalogKind;
use crate::error::Error;
use crate::model::*;
use crate::xml::Elem;

const OBJECT_KINDS: &[CatalogKind] = &[CatalogKind::Vehicle, CatalogKind::Pedestrian, CatalogKind::MiscObject];

pub(crate) fn read_entities(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<(Vec<Entity>, Vec<EntitySelection>), Error> {
    let mut entities: Vec<Entity> = Vec::new();
    let mut selections = Vec::new();
    for c in e.children() {
        match c.name.as_str() {
            "ScenarioObject" => {
                let ent = read_scenario_object(r, cx, c)?;
                if let Some(prev) = entities.iter().position(|x| x.name == ent.name) {
                    r.warn(cx.loc(c.pos), format!("entity '{}' is defined twice; the later definition wins", ent.name));
                    entities.remove(prev);
                }
                entities.push(ent);
            }
            "EntitySelection" => selections.push(read_selection(cx, c)?),
            _ => r.unsupported(cx, c, "Entities"),
        }
    }
    Ok((entities, selections))
}

pub(crate) fn read_scenario_object(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Entity, Error> {
    let name = cx.text(e, "name")?;
    let mut object = None;
    let mut controllers = Vec::new();
    for c in e.children() {
        match c.name.as_str() {
            "ObjectController" => {
                if let Some(mut ctrl) = read_object_controller(r, cx, c)? {
                    // The wrapper's name, when it has one, is the controller's name (esmini's
                    // ScenarioReader::parseEntities: Controller::SetName); activations use it.
                    if let Some(n) = cx.opt_text(c, "name")?.filter(|n| !n.is_empty()) {
                        ctrl.name = n;
                    }
                    controllers.push(ctrl);
                }
            }
            "CatalogReference" | "Vehicle" | "Pedestrian" | "MiscObject" | "ExternalObjectReference" => {
                object = Some(read_entity_object(r, cx, c)?);
            }
            _ => r.unsupported(cx, c, "ScenarioObject"),
        }
    }
    let object = object.ok_or_else(|| {
        cx.err(
            crate::error::ErrorKind::Structure,
            e.pos,
            format!("ScenarioObject '{name}' needs a Vehicle, Pedestrian, MiscObject, ExternalObjectReference or CatalogReference"),
        )
    })?;
    Ok(Entity { name, object, controllers, origin: cx.loc(e.pos) })
}

fn read_entity_object(r: &mut Reader, cx: &Cx, c: &Elem) -> Result<EntityObject, Error> {
    match c.name.as_str() {
        "CatalogReference" => r.catalog_entry_or(cx, c, OBJECT_KINDS, read_entity_object_entry, |name| EntityObject::External { name }),
        "ExternalObjectReference" => Ok(EntityObject::External { name: cx.text(c, "name")? }),
        _ => read_entity_object_entry(r, cx, c, &[]),
    }
}

pub(crate) fn read_entity_object_entry(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<EntityObject, Error> {
    match e.name.as_str() {
        "Vehicle" => Ok(EntityObject::Vehicle(read_vehicle(r, cx, e, asg)?)),
        "Pedestrian" => Ok(EntityObject::Pedestrian(read_pedestrian(r, cx, e, asg)?)),
        "MiscObject" => Ok(EntityObject::MiscObject(read_misc_object(r, cx, e, asg)?)),
        _ => Err(cx.unexpected(e, "ScenarioObject", "Vehicle, Pedestrian, MiscObject")),
    }
}

fn read_vehicle(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<Vehicle, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    let perf = cx.child(e, "Performance")?;
    let axles = cx.child(e, "Axles")?;
    let trailer = match e.child("Trailer") {
        None => None,
        Some(t) => match t.first_child() {
            Some(c) if c.name == "TrailerRef" => Some(Trailer::Ref(cx.reference(c, "entityRef")?)),
            Some(c) if c.name == "Trailer" => Some(Trailer::Entity(Box::new(read_scenario_object(r, &cx, c)?))),
            Some(c) if c.name == "EntityRef" => Some(Trailer::Ref(cx.reference(c, "entityRef")?)),
            Some(c) => return Err(cx.unexpected(c, "Trailer", "Trailer, TrailerRef")),
            None => None,
        },
    };
    Ok(Vehicle {
        name: cx.text(e, "name")?,
        // esmini compares the category exactly and keeps its default, car, for any other text
        category: cx.enum_or_esmini_default(e, "vehicleCategory", VehicleCategory::Car)?,
        role: cx.opt_enum(e, "role")?,
        mass: cx.opt_f64(e, "mass")?,
        model3d: cx.opt_text(e, "model3d")?,
        bounding_box: read_bounding_box(&cx, cx.child(e, "BoundingBox")?)?,
        performance: Performance {
            max_speed: cx.f64(perf, "maxSpeed")?,
            max_acceleration: cx.f64(perf, "maxAcceleration")?,
            max_deceleration: cx.f64(perf, "maxDeceleration")?,
            max_acceleration_rate: cx.opt_f64(perf, "maxAccelerationRate")?,
            max_deceleration_rate: cx.opt_f64(perf, "maxDecelerationRate")?,
        },
        axles: Axles {
            front: axles.child("FrontAxle").map(|a| read_axle(&cx, a)).transpose()?,
            rear: read_axle(&cx, cx.child(axles, "RearAxle")?)?,
            additional: axles.children_named("AdditionalAxle").map(|a| read_axle(&cx, a)).collect::<Result<_, _>>()?,
        },
        properties: read_properties(&cx, e.child("Properties"))?,
        trailer_hitch: e.child("TrailerHitch").map(|t| cx.f64(t, "dx")).transpose()?,
        trailer_coupler: e.child("TrailerCoupler").map(|t| cx.f64(t, "dx")).transpose()?,
        trailer,
        parameters,
    })
}

fn read_pedestrian(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<Pedestrian, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    Ok(Pedestrian {
        name: cx.text(e, "name")?,
        // as for vehicles: esmini's default is pedestrian
        category: cx.enum_or_esmini_default(e, "pedestrianCategory", PedestrianCategory::Pedestrian)?,
        role: cx.opt_enum(e, "role")?,
        mass: cx.f64_or(e, "mass", 0.0)?,
        // `model` is the 1.0 spelling of `model3d`.
        model3d: match cx.opt_text(e, "model3d")? {
            Some(m) => Some(m),
            None => cx.opt_text(e, "model")?,
        },
        bounding_box: read_bounding_box(&cx, cx.child(e, "BoundingBox")?)?,
        properties: read_properties(&cx, e.child("Properties"))?,
        parameters,
    })
}

fn read_misc_object(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<MiscObject, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    Ok(MiscObject {
        name: cx.text(e, "name")?,
        category: cx.enum_(e, "miscObjectCategory")?,
        mass: cx.f64_or(e, "mass", 0.0)?,
        model3d: cx.opt_text(e, "model3d")?,
        bounding_box: read_bounding_box(&cx, cx.child(e, "BoundingBox")?)?,
        properties: read_properties(&cx, e.child("Properties"))?,
        parameters,
    })
}

/// esmini reads a bounding box and the axles with `std::stof`, which stops the run on text that
/// is not a number: no `--lenient` reading of such text here (`f64_exact`).
pub(crate) fn read_bounding_box(cx: &Cx, e: &Elem) -> Result<BoundingBox, Error> {
    let c = cx.child(e, "Center")?;
    let d = cx.child(e, "Dimensions")?;
    Ok(BoundingBox {
        center: Vec3 { x: cx.f64_exact(c, "x")?, y: cx.f64_exact(c, "y")?, z: cx.f64_exact(c, "z")? },
        width: cx.f64_exact(d, "width")?,
        length: cx.f64_exact(d, "length")?,
        height: cx.f64_exact(d, "height")?,
    })
}

fn read_axle(cx: &Cx, e: &Elem) -> Result<Axle, Error> {
    Ok(Axle {
        max_steering: cx.f64_exact(e, "maxSteering")?,
        wheel_diameter: cx.f64_exact(e, "wheelDiameter")?,
        track_width: cx.f64_exact(e, "trackWidth")?,
        position_x: cx.f64_exact(e, "positionX")?,
        position_z: cx.f64_exact(e, "positionZ")?,
    })
}

pub(crate) fn read_properties(cx: &Cx, e: Option<&Elem>) -> Result<Properties, Error> {
    let mut p = Properties::default();
    if let Some(e) = e {
        for c in e.children() {
            match c.name.as_str() {
                "Property" => p.properties.push((cx.text(c, "name")?, cx.text(c, "value")?)),
                "File" => p.files.push(cx.text(c, "filepath")?),
                _ => {}
            }
        }
    }
    Ok(p)
}

pub(crate) fn read_controller(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<Controller, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    Ok(Controller {
        name: cx.text(e, "name")?,
        controller_type: cx.opt_enum(e, "controllerType")?,
        properties: read_properties(&cx, e.child("Properties"))?,
        parameters,
        origin: cx.loc(e.pos),
    })
}

/// ObjectController (or the controller part of AssignControllerAction): inline or from a catalog.
pub(crate) fn read_object_controller(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Option<Controller>, Error> {
    let Some(c) = e.first_child() else { return Ok(None) };
    match c.name.as_str() {
        "Controller" => Ok(Some(read_controller(r, cx, c, &[])?)),
        "CatalogReference" => r.catalog_entry_or(cx, c, &[CatalogKind::Controller], |r, cx, e, asg| read_controller(r, cx, e, asg).map(Some), |_| None),
        "ObjectController" => read_object_controller(r, cx, c),
        _ => Err(cx.unexpected(c, &e.name, "Controller, CatalogReference")),
    }
}

fn read_selection(cx: &Cx, e: &Elem) -> Result<EntitySelection, Error> {
    let mut members = Vec::new();
    if let Some(m) = e.child("Members") {
        for c in m.children() {
            match c.name.as_str() {
                "EntityRef" => members.push(SelectionMember::Entity(cx.reference(c, "entityRef")?)),
                "ByType" => members.push(SelectionMember::ByType(cx.enum_(c, "objectType")?)),
                _ => return Err(cx.unexpected(c, "Members", "EntityRef, ByType")),
            }
        }
    }
    Ok(EntitySelection { name: cx.text(e, "name")?, members, origin: cx.loc(e.pos) })
}

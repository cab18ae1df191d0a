//! Triggers and conditions.

use super::position::read_position;
use super::Reader;
use crate::attr::Cx;
use crate::error::Error;
use crate::model::*;
use crate::xml::Elem;

/// A StartTrigger / StopTrigger element.
pub(crate) fn read_trigger(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Trigger, Error> {
    let mut groups = Vec::new();
    for g in e.children() {
        if g.name != "ConditionGroup" {
            r.unsupported(cx, g, &e.name);
            continue;
        }
        let conditions = g.children_named("Condition").map(|c| read_condition(r, cx, c)).collect::<Result<Vec<_>, Error>>()?;
        groups.push(ConditionGroup { conditions });
    }
    Ok(Trigger { groups })
}

fn read_condition(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Condition, Error> {
    let c = cx.choice(e, "ByEntityCondition or ByValueCondition")?;
    let kind = match c.name.as_str() {
        "ByEntityCondition" => by_entity(r, cx, c)?,
        "ByValueCondition" => by_value(r, cx, c)?,
        _ => {
            r.unsupported(cx, c, "Condition");
            ConditionKind::Unsupported { element: c.name.clone() }
        }
    };
    Ok(Condition {
        name: cx.opt_text(e, "name")?.unwrap_or_default(),
        delay: cx.f64_or(e, "delay", 0.0)?,
        edge: cx.opt_enum(e, "conditionEdge")?.unwrap_or(ConditionEdge::None),
        kind,
        origin: cx.loc(e.pos),
    })
}

fn options(cx: &Cx, e: &Elem) -> Result<DistanceOptions, Error> {
    Ok(DistanceOptions {
        freespace: cx.bool_or(e, "freespace", false)?,
        coordinate_system: cx.opt_enum(e, "coordinateSystem")?,
        relative_distance_type: cx.opt_enum(e, "relativeDistanceType")?,
        routing_algorithm: cx.opt_enum(e, "routingAlgorithm")?,
        along_route: cx.opt_bool(e, "alongRoute")?,
    })
}

fn by_entity(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<ConditionKind, Error> {
    let te = cx.child(e, "TriggeringEntities")?;
    let rule = cx.opt_enum(te, "triggeringEntitiesRule")?.unwrap_or(TriggeringEntitiesRule::Any);
    let entities = te.children_named("EntityRef").map(|x| cx.reference(x, "entityRef")).collect::<Result<Vec<_>, _>>()?;
    let ec = cx.child(e, "EntityCondition")?;
    let c = cx.choice(ec, "an entity condition")?;
    let condition = match c.name.as_str() {
        "EndOfRoadCondition" => EntityCondition::EndOfRoad { duration: cx.f64_or(c, "duration", 0.0)? },
        "OffroadCondition" => EntityCondition::Offroad { duration: cx.f64_or(c, "duration", 0.0)? },
        "StandStillCondition" => EntityCondition::StandStill { duration: cx.f64_or(c, "duration", 0.0)? },
        "CollisionCondition" => {
            let t = cx.choice(c, "EntityRef or ByType")?;
            let target = match t.name.as_str() {
                "EntityRef" => CollisionTarget::Entity(cx.reference(t, "entityRef")?),
                "ByType" => CollisionTarget::ByType(cx.enum_(t, "type")?),
                _ => return Err(cx.unexpected(t, "CollisionCondition", "EntityRef, ByType")),
            };
            EntityCondition::Collision { target }
        }
        "TimeHeadwayCondition" => EntityCondition::TimeHeadway {
            entity: cx.reference(c, "entityRef")?,
            value: cx.f64(c, "value")?,
            rule: cx.enum_(c, "rule")?,
            options: options(cx, c)?,
        },
        "TimeToCollisionCondition" => {
            let t = cx.choice(cx.child(c, "TimeToCollisionConditionTarget")?, "Position or EntityRef")?;
            let target = match t.name.as_str() {
                "EntityRef" => TtcTarget::Entity(cx.reference(t, "entityRef")?),
                "Position" => TtcTarget::Position(read_position(r, cx, t)?),
                _ => return Err(cx.unexpected(t, "TimeToCollisionConditionTarget", "Position, EntityRef")),
            };
            EntityCondition::TimeToCollision { target, value: cx.f64(c, "value")?, rule: cx.enum_(c, "rule")?, options: options(cx, c)? }
        }
        "AccelerationCondition" => {
            EntityCondition::Acceleration { value: cx.f64(c, "value")?, rule: cx.enum_(c, "rule")?, direction: cx.opt_enum(c, "direction")? }
        }
        "SpeedCondition" => EntityCondition::Speed { value: cx.f64(c, "value")?, rule: cx.enum_(c, "rule")?, direction: cx.opt_enum(c, "direction")? },
        "RelativeSpeedCondition" => EntityCondition::RelativeSpeed {
            entity: cx.reference(c, "entityRef")?,
            value: cx.f64(c, "value")?,
            rule: cx.enum_(c, "rule")?,
            direction: cx.opt_enum(c, "direction")?,
        },
        "TraveledDistanceCondition" => EntityCondition::TraveledDistance { value: cx.f64(c, "value")? },
        "ReachPositionCondition" => {
            EntityCondition::ReachPosition { position: read_position(r, cx, cx.child(c, "Position")?)?, tolerance: cx.f64(c, "tolerance")? }
        }
        "DistanceCondition" => EntityCondition::Distance {
            position: read_position(r, cx, cx.child(c, "Position")?)?,
            value: cx.f64(c, "value")?,
            rule: cx.enum_(c, "rule")?,
            options: options(cx, c)?,
        },
        "RelativeDistanceCondition" => EntityCondition::RelativeDistance {
            entity: cx.reference(c, "entityRef")?,
            value: cx.f64(c, "value")?,
            rule: cx.enum_(c, "rule")?,
            options: options(cx, c)?,
        },
        "RelativeClearanceCondition" => EntityCondition::RelativeClearance {
            entities: c.children_named("EntityRef").map(|x| cx.reference(x, "entityRef")).collect::<Result<_, _>>()?,
            opposite_lanes: cx.bool_or(c, "oppositeLanes", false)?,
            free_space: cx.bool_or(c, "freeSpace", false)?,
            distance_forward: cx.opt_f64(c, "distanceForward")?,
            distance_backward: cx.opt_f64(c, "distanceBackward")?,
            lane_ranges: c
                .children_named("RelativeLaneRange")
                .map(|l| {
                    let conv = |n: &str| -> Result<Option<i32>, Error> { Ok(cx.opt_i64(l, n)?.and_then(|v| i32::try_from(v).ok())) };
                    Ok((conv("from")?, conv("to")?))
                })
                .collect::<Result<_, Error>>()?,
        },
        "AngleCondition" => EntityCondition::Angle {
            angle_type: cx.enum_(c, "angleType")?,
            angle: cx.f64(c, "angle")?,
            tolerance: cx.f64(c, "angleTolerance")?,
            coordinate_system: cx.opt_enum(c, "coordinateSystem")?,
        },
        "RelativeAngleCondition" => EntityCondition::RelativeAngle {
            entity: cx.reference(c, "entityRef")?,
            angle_type: cx.enum_(c, "angleType")?,
            angle: cx.f64(c, "angle")?,
            tolerance: cx.f64(c, "angleTolerance")?,
            coordinate_system: cx.opt_enum(c, "coordinateSystem")?,
        },
        _ => {
            r.unsupported(cx, c, "EntityCondition");
            return Ok(ConditionKind::Unsupported { element: c.name.clone() });
        }
    };
    Ok(ConditionKind::ByEntity { rule, entities, condition })
}

fn by_value(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<ConditionKind, Error> {
    let c = cx.choice(e, "a value condition")?;
    let v = match c.name.as_str() {
        "ParameterCondition" => {
            ValueCondition::Parameter { parameter: cx.name_ref(c, "parameterRef")?, value: cx.text(c, "value")?, rule: cx.enum_(c, "rule")? }
        }
        "VariableCondition" => ValueCondition::Variable { variable: cx.name_ref(c, "variableRef")?, value: cx.text(c, "value")?, rule: cx.enum_(c, "rule")? },
        "TimeOfDayCondition" => ValueCondition::TimeOfDay { date_time: cx.text(c, "dateTime")?, rule: cx.enum_(c, "rule")? },
        "SimulationTimeCondition" => ValueCondition::SimulationTime { value: cx.f64(c, "value")?, rule: cx.enum_(c, "rule")? },
        "StoryboardElementStateCondition" => ValueCondition::StoryboardElementState {
            element_type: cx.enum_(c, "storyboardElementType")?,
            element: cx.reference(c, "storyboardElementRef")?,
            state: cx.enum_(c, "state")?,
        },
        "UserDefinedValueCondition" => ValueCondition::UserDefinedValue { name: cx.text(c, "name")?, value: cx.text(c, "value")?, rule: cx.enum_(c, "rule")? },
        "TrafficSignalCondition" => ValueCondition::TrafficSignal { name: cx.reference(c, "name")?, state: cx.text(c, "state")? },
        "TrafficSignalControllerCondition" => {
            ValueCondition::TrafficSignalController { controller: cx.reference(c, "trafficSignalControllerRef")?, phase: cx.text(c, "phase")? }
        }
        _ => {
            r.unsupported(cx, c, "ByValueCondition");
            return Ok(ConditionKind::Unsupported { element: c.name.clone() });
        }
    };
    Ok(ConditionKind::ByValue(v))
}

//! Global actions.

use super::environment::read_environment_ref;
use super::position::read_position;
use super::Reader;
use crate::attr::Cx;
use crate::error::Error;
use crate::model::*;
use crate::xml::Elem;

fn unsupported(r: &mut Reader, cx: &Cx, e: &Elem, parent: &str) -> ActionKind {
    r.unsupported(cx, e, parent);
    ActionKind::Unsupported { element: e.name.clone() }
}

fn modify_rule(cx: &Cx, m: &Elem) -> Result<ModifyRule, Error> {
    let rule = cx.child(m, "Rule")?;
    let c = cx.choice(rule, "AddValue or MultiplyByValue")?;
    let kind = match c.name.as_str() {
        "AddValue" => ModifyKind::Add,
        "MultiplyByValue" => ModifyKind::Multiply,
        _ => return Err(cx.unexpected(c, "Rule", "AddValue, MultiplyByValue")),
    };
    Ok(ModifyRule { kind, value: cx.f64(c, "value")? })
}

fn traffic_definition(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<String, Error> {
    Ok(match e.child("TrafficDefinition") {
        Some(d) => {
            r.warn(cx.loc(d.pos), "TrafficDefinition: only its name is kept (vehicle and controller distributions are not modelled)");
            cx.opt_text(d, "name")?.unwrap_or_default()
        }
        None => String::new(),
    })
}

pub(crate) fn read_global_action(r: &mut Reader, cx: &Cx, wrapper: &Elem) -> Result<ActionKind, Error> {
    let e = cx.choice(wrapper, "a global action")?;
    let a = match e.name.as_str() {
        "EnvironmentAction" => GlobalAction::Environment(read_environment_ref(r, cx, e)?),
        "EntityAction" => {
            let entity = cx.reference(e, "entityRef")?;
            let c = cx.choice(e, "AddEntityAction or DeleteEntityAction")?;
            match c.name.as_str() {
                "AddEntityAction" => GlobalAction::AddEntity { entity, position: read_position(r, cx, cx.child(c, "Position")?)? },
                "DeleteEntityAction" => GlobalAction::DeleteEntity { entity },
                _ => return Ok(unsupported(r, cx, c, "EntityAction")),
            }
        }
        "ParameterAction" | "VariableAction" => {
            let is_param = e.name == "ParameterAction";
            let name = cx.name_ref(e, if is_param { "parameterRef" } else { "variableRef" })?;
            let c = cx.choice(e, "SetAction or ModifyAction")?;
            match (c.name.as_str(), is_param) {
                ("SetAction", true) => GlobalAction::ParameterSet { parameter: name, value: cx.text(c, "value")? },
                ("SetAction", false) => GlobalAction::VariableSet { variable: name, value: cx.text(c, "value")? },
                ("ModifyAction", true) => GlobalAction::ParameterModify { parameter: name, rule: modify_rule(cx, c)? },
                ("ModifyAction", false) => GlobalAction::VariableModify { variable: name, rule: modify_rule(cx, c)? },
                _ => return Ok(unsupported(r, cx, c, &e.name)),
            }
        }
        "InfrastructureAction" => {
            let tsa = cx.child(e, "TrafficSignalAction")?;
            let c = cx.choice(tsa, "TrafficSignalControllerAction or TrafficSignalStateAction")?;
            match c.name.as_str() {
                "TrafficSignalStateAction" => GlobalAction::TrafficSignalState { name: cx.reference(c, "name")?, state: cx.text(c, "state")? },
                "TrafficSignalControllerAction" => {
                    GlobalAction::TrafficSignalController { controller: cx.reference(c, "trafficSignalControllerRef")?, phase: cx.text(c, "phase")? }
                }
                _ => return Ok(unsupported(r, cx, c, "TrafficSignalAction")),
            }
        }
        "TrafficAction" => {
            let c = cx.choice(e, "a traffic action")?;
            match c.name.as_str() {
                "TrafficSourceAction" => GlobalAction::TrafficSource {
                    position: read_position(r, cx, cx.child(c, "Position")?)?,
                    radius: cx.f64(c, "radius")?,
                    rate: cx.f64(c, "rate")?,
                    velocity: cx.opt_f64(c, "velocity")?,
                    definition: traffic_definition(r, cx, c)?,
                },
                "TrafficSinkAction" => GlobalAction::TrafficSink {
                    position: read_position(r, cx, cx.child(c, "Position")?)?,
                    radius: cx.f64(c, "radius")?,
                    rate: cx.opt_f64(c, "rate")?,
                    definition: traffic_definition(r, cx, c)?,
                },
                "TrafficSwarmAction" => GlobalAction::TrafficSwarm {
                    central_entity: cx.reference(cx.child(c, "CentralObject")?, "entityRef")?,
                    inner_radius: cx.f64(c, "innerRadius")?,
                    semi_major_axis: cx.f64(c, "semiMajorAxis")?,
                    semi_minor_axis: cx.f64(c, "semiMinorAxis")?,
                    offset: cx.f64_or(c, "offset", 0.0)?,
                    number_of_vehicles: cx.u32_or(c, "numberOfVehicles", 0)?,
                    velocity: cx.opt_f64(c, "velocity")?,
                    definition: traffic_definition(r, cx, c)?,
                },
                "TrafficAreaAction" => {
                    r.warn(cx.loc(c.pos), "TrafficAreaAction: the area's geometry is not modelled");
                    GlobalAction::TrafficArea { continuous: cx.bool_or(c, "continuous", false)?, number_of_entities: cx.u32_or(c, "numberOfEntities", 0)? }
                }
                "TrafficStopAction" => GlobalAction::TrafficStop { name: cx.opt_text(e, "trafficName")? },
                _ => return Ok(unsupported(r, cx, c, "TrafficAction")),
            }
        }
        "SetMonitorAction" => GlobalAction::SetMonitor { monitor: cx.text(e, "monitorRef")?, value: cx.bool(e, "value")? },
        _ => return Ok(unsupported(r, cx, e, "GlobalAction")),
    };
    Ok(ActionKind::Global(a))
}

//! The OpenSCENARIO pieces every part of the storyboard uses: world positions, the private
//! and global actions the export writes, and simulation-time conditions, each in the form of
//! the version written.

use crate::options::OscVersion;
use crate::xml::{num, time, El};

/// A `Position` holding a `WorldPosition` (x, y, heading); no z, so a simulator puts the entity
/// on the road surface.
pub(crate) fn world(x: f64, y: f64, h: f64) -> El {
    El::new("Position").child(El::new("WorldPosition").num("x", x).num("y", y).num("h", h))
}

/// `PrivateAction/TeleportAction` to a world position.
pub(crate) fn teleport(x: f64, y: f64, h: f64) -> El {
    El::new("PrivateAction").child(El::new("TeleportAction").child(world(x, y, h)))
}

/// `PrivateAction/LongitudinalAction/SpeedAction`: `speed` at once.
pub(crate) fn speed(speed: f64) -> El {
    El::new("PrivateAction").child(
        El::new("LongitudinalAction").child(
            El::new("SpeedAction")
                .child(El::new("SpeedActionDynamics").attr("dynamicsShape", "step").num("value", 0.0).attr("dynamicsDimension", "time"))
                .child(El::new("SpeedActionTarget").child(El::new("AbsoluteTargetSpeed").num("value", speed))),
        ),
    )
}

/// Activates the entity's assigned controller in both domains.
pub(crate) fn activate_controller(version: OscVersion) -> El {
    let activate = El::new("ActivateControllerAction").attr("lateral", "true").attr("longitudinal", "true");
    match version {
        // 1.0 has it directly under PrivateAction (deprecated from 1.1 on)
        OscVersion::V1_0 => El::new("PrivateAction").child(activate),
        OscVersion::V1_3 => El::new("PrivateAction").child(El::new("ControllerAction").child(activate)),
    }
}

/// `GlobalAction/EntityAction/AddEntityAction` at a world position.
pub(crate) fn add_entity(entity: &str, x: f64, y: f64, h: f64) -> El {
    El::new("GlobalAction").child(El::new("EntityAction").attr("entityRef", entity).child(El::new("AddEntityAction").child(world(x, y, h))))
}

/// `GlobalAction/EntityAction/DeleteEntityAction`.
pub(crate) fn delete_entity(entity: &str) -> El {
    El::new("GlobalAction").child(El::new("EntityAction").attr("entityRef", entity).child(El::new("DeleteEntityAction")))
}

/// Sets a boolean flag: a variable in 1.3, a parameter in 1.0 (which has no variables).
pub(crate) fn set_flag(version: OscVersion, name: &str) -> El {
    let set = El::new("SetAction").attr("value", "true");
    match version {
        OscVersion::V1_0 => El::new("GlobalAction").child(El::new("ParameterAction").attr("parameterRef", name).child(set)),
        OscVersion::V1_3 => El::new("GlobalAction").child(El::new("VariableAction").attr("variableRef", name).child(set)),
    }
}

/// An `Action` element of a story event.
pub(crate) fn action(name: String, inner: El) -> El {
    El::new("Action").attr("name", name).child(inner)
}

/// A `Condition`.
pub(crate) fn condition(name: String, inner: El) -> El {
    El::new("Condition").attr("name", name).num("delay", 0.0).attr("conditionEdge", "none").child(inner)
}

/// The simulation time is past `seconds`.
pub(crate) fn after(name: String, seconds: f64) -> El {
    condition(name, El::new("ByValueCondition").child(El::new("SimulationTimeCondition").attr("value", time(seconds)).attr("rule", "greaterThan")))
}

/// The simulation time is before `seconds`.
pub(crate) fn before(name: String, seconds: f64) -> El {
    condition(name, El::new("ByValueCondition").child(El::new("SimulationTimeCondition").attr("value", time(seconds)).attr("rule", "lessThan")))
}

/// A condition on `entity` (`ByEntityCondition`).
pub(crate) fn by_entity(name: String, entity: &str, inner: El) -> El {
    condition(
        name,
        El::new("ByEntityCondition")
            .child(El::new("TriggeringEntities").attr("triggeringEntitiesRule", "any").child(El::new("EntityRef").attr("entityRef", entity)))
            .child(El::new("EntityCondition").child(inner)),
    )
}

/// A trigger of one condition group per entry of `groups` (a group's conditions must all
/// hold; one group suffices).
pub(crate) fn trigger(name: &'static str, groups: Vec<Vec<El>>) -> El {
    El::new(name).children(groups.into_iter().map(|g| El::new("ConditionGroup").children(g)))
}

/// A numeric rule: `at least` / `at most` as the version can say them (1.0 has only the strict
/// comparisons; the boundary of a closed interval is a set of measure zero).
pub(crate) fn rule(version: OscVersion, at_least: bool) -> &'static str {
    match (version, at_least) {
        (OscVersion::V1_0, true) => "greaterThan",
        (OscVersion::V1_0, false) => "lessThan",
        (OscVersion::V1_3, true) => "greaterOrEqual",
        (OscVersion::V1_3, false) => "lessOrEqual",
    }
}

/// `v` formatted for messages.
pub(crate) fn show(v: f64) -> String {
    num(v)
}

//! Names that must refer to something the scenario declares: entities (Init, actors, actions,
//! conditions, positions), storyboard elements, global parameters and variables, traffic
//! signal controllers. A name that refers to nothing is a *problem*: the caller decides whether
//! it stops the file (osc2cr's default) or is reported and passed over (`--lenient`).
//!
//! Roads, lanes and traffic signals are checked where the road network is loaded
//! (`engine::road_references`); catalogs, catalog entries and `$parameter` expressions are
//! resolved, and fail, while reading. Each problem is put at the attribute that holds the name
//! (the reader keeps where every reference was written: [`ReferenceSite`]).

mod storyboard;

use std::collections::BTreeSet;

use crate::error::{Diagnostic, Location};
use crate::model::*;

/// Every position of the scenario with the origin of the element that holds it (Init and
/// storyboard actions, conditions, routes, trajectories), in file order.
pub fn positions(s: &Scenario) -> Vec<(&Position, &Location)> {
    let mut out = Vec::new();
    for_each_action(s, |a, _| action_positions(a, &mut out));
    for_each_condition(s, |c| {
        if let ConditionKind::ByEntity { condition, .. } = &c.kind {
            match condition {
                EntityCondition::ReachPosition { position, .. } | EntityCondition::Distance { position, .. } => nested_positions(position, &c.origin, &mut out),
                EntityCondition::TimeToCollision { target: TtcTarget::Position(position), .. } => nested_positions(position, &c.origin, &mut out),
                _ => {}
            }
        }
    });
    out
}

/// Calls `f` for every action of the storyboard with the entities it acts on (Init private
/// actions: their entity; story actions: the maneuver group's actors; global actions: none).
pub fn for_each_action<'a>(s: &'a Scenario, mut f: impl FnMut(&'a Action, &[&'a str])) {
    let init = &s.storyboard.init;
    for a in &init.global {
        f(a, &[]);
    }
    for p in &init.private {
        for a in &p.actions {
            f(a, &[p.entity.as_str()]);
        }
    }
    for story in &s.storyboard.stories {
        for act in &story.acts {
            for mg in &act.maneuver_groups {
                let actors: Vec<&str> = mg.actors.iter().map(String::as_str).collect();
                for m in &mg.maneuvers {
                    for e in &m.events {
                        for a in &e.actions {
                            f(a, &actors);
                        }
                    }
                }
            }
        }
    }
}

/// Calls `f` for every condition of every trigger of the storyboard.
pub fn for_each_condition<'a>(s: &'a Scenario, mut f: impl FnMut(&'a Condition)) {
    let trigger = |t: &'a Option<Trigger>, f: &mut dyn FnMut(&'a Condition)| {
        for g in t.iter().flat_map(|t| &t.groups) {
            for c in &g.conditions {
                f(c);
            }
        }
    };
    trigger(&s.storyboard.stop_trigger, &mut f);
    for story in &s.storyboard.stories {
        for act in &story.acts {
            trigger(&act.start_trigger, &mut f);
            trigger(&act.stop_trigger, &mut f);
            for mg in &act.maneuver_groups {
                for m in &mg.maneuvers {
                    for e in &m.events {
                        trigger(&e.start_trigger, &mut f);
                    }
                }
            }
        }
    }
}

fn action_positions<'a>(a: &'a Action, out: &mut Vec<(&'a Position, &'a Location)>) {
    let o = &a.origin;
    match &a.kind {
        ActionKind::Private(p) => match p {
            PrivateAction::Teleport(pos) | PrivateAction::AcquirePosition(pos) => nested_positions(pos, o, out),
            PrivateAction::Synchronize { target_position_master, target_position, .. } => {
                nested_positions(target_position_master, o, out);
                nested_positions(target_position, o, out);
            }
            PrivateAction::AssignRoute(r) => route_positions(r, o, out),
            PrivateAction::FollowTrajectory { trajectory, .. } => trajectory_positions(trajectory, o, out),
            _ => {}
        },
        ActionKind::Global(g) => match g {
            GlobalAction::AddEntity { position, .. } => nested_positions(position, o, out),
            GlobalAction::TrafficSource { position, .. } | GlobalAction::TrafficSink { position, .. } => nested_positions(position, o, out),
            _ => {}
        },
        _ => {}
    }
}

/// A position and the positions inside it (a route's waypoints, a trajectory's vertices).
fn nested_positions<'a>(p: &'a Position, o: &'a Location, out: &mut Vec<(&'a Position, &'a Location)>) {
    out.push((p, o));
    match p {
        Position::Route { route, .. } => route_positions(route, o, out),
        Position::Trajectory { trajectory, .. } => trajectory_positions(trajectory, o, out),
        _ => {}
    }
}

fn route_positions<'a>(r: &'a Route, o: &'a Location, out: &mut Vec<(&'a Position, &'a Location)>) {
    let _ = o;
    for w in &r.waypoints {
        nested_positions(&w.position, &r.origin, out);
    }
}

fn trajectory_positions<'a>(t: &'a Trajectory, o: &'a Location, out: &mut Vec<(&'a Position, &'a Location)>) {
    let _ = o;
    let o = &t.origin;
    match &t.shape {
        Shape::Polyline(vs) => vs.iter().for_each(|v| nested_positions(&v.position, o, out)),
        Shape::Clothoid { position: Some(p), .. } => nested_positions(p, o, out),
        Shape::Clothoid { position: None, .. } => {}
        Shape::ClothoidSpline { segments, .. } => segments.iter().filter_map(|s| s.position_start.as_ref()).for_each(|p| nested_positions(p, o, out)),
        Shape::Nurbs { control_points, .. } => control_points.iter().for_each(|c| nested_positions(&c.position, o, out)),
    }
}

/// Where a reference was written: the attribute (`entityRef`, `roadId`, `laneId`,
/// `storyboardElementRef`, …), its resolved value and the position of the value.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceSite {
    pub attribute: String,
    pub value: String,
    pub location: Location,
}

/// Every name of the scenario that refers to nothing it declares, as a problem at the attribute
/// that holds the name.
pub fn unresolved(s: &Scenario) -> Vec<Diagnostic> {
    let mut entities = BTreeSet::new();
    for e in &s.entities {
        declare_entity(e, &mut entities, 0);
    }
    for sel in &s.entity_selections {
        entities.insert(sel.name.as_str());
    }
    let elements = storyboard::Elements::of(s);
    let mut out = Vec::new();
    // `within`: the element holding the attribute; the problem is put at the attribute itself
    let at = |within: &'_ Location, attribute: &str, value: &str| -> Location { s.reference_site(within, attribute, |v| v == value).clone() };
    let entity = |name: &str, within: &Location, attribute: &str, what: &str, out: &mut Vec<Diagnostic>| {
        if !entities.contains(name) {
            out.push(problem(&at(within, attribute, name), format!("{what} `{name}` is not an entity of the scenario")));
        }
    };
    let signal_controller = |name: &str, within: &Location, attribute: &str, what: &str, out: &mut Vec<Diagnostic>| {
        if !s.road_network.traffic_signal_controllers.iter().any(|c| c.name == name) {
            out.push(problem(&at(within, attribute, name), format!("{what}: traffic signal controller `{name}` is not declared in the RoadNetwork")));
        }
    };

    for p in &s.storyboard.init.private {
        entity(&p.entity, &p.origin, "entityRef", "Init actions for entity", &mut out);
    }
    for c in &s.road_network.traffic_signal_controllers {
        if let Some(r) = &c.reference {
            signal_controller(r, &c.origin, "reference", &format!("TrafficSignalController `{}`", c.name), &mut out);
        }
    }
    for story in &s.storyboard.stories {
        for act in &story.acts {
            for mg in &act.maneuver_groups {
                for a in &mg.actors {
                    entity(a, &mg.origin, "entityRef", &format!("actor of maneuver group `{}`:", mg.name), &mut out);
                }
                out.extend(actorless_private_actions(mg));
            }
        }
    }
    for_each_action(s, |a, _| {
        let what = a.kind.element_name();
        for (attribute, name) in action_entities(&a.kind) {
            entity(name, &a.origin, attribute, &format!("{what}: entity"), &mut out);
        }
        match &a.kind {
            ActionKind::Global(GlobalAction::ParameterSet { parameter, .. }) | ActionKind::Global(GlobalAction::ParameterModify { parameter, .. })
                if s.parameter(parameter).is_none() =>
            {
                out.push(problem(&at(&a.origin, "parameterRef", parameter), format!("{what}: parameter `{parameter}` is not declared by the scenario")));
            }
            ActionKind::Global(GlobalAction::VariableSet { variable, .. }) | ActionKind::Global(GlobalAction::VariableModify { variable, .. })
                if !declares(&s.variables, variable) =>
            {
                out.push(problem(&at(&a.origin, "variableRef", variable), format!("{what}: variable `{variable}` is not declared by the scenario")));
            }
            ActionKind::Global(GlobalAction::TrafficSignalController { controller, .. }) => {
                signal_controller(controller, &a.origin, "trafficSignalControllerRef", what, &mut out);
            }
            _ => {}
        }
    });
    for_each_condition(s, |c| {
        let what = c.kind.element_name();
        match &c.kind {
            ConditionKind::ByEntity { entities: triggering, condition, .. } => {
                for name in triggering {
                    entity(name, &c.origin, "entityRef", &format!("{what}: triggering entity"), &mut out);
                }
                for name in condition_entities(condition) {
                    entity(name, &c.origin, "entityRef", &format!("{what}: entity"), &mut out);
                }
            }
            ConditionKind::ByValue(v) => match v {
                ValueCondition::Parameter { parameter, .. } if s.parameter(parameter).is_none() => {
                    out.push(problem(&at(&c.origin, "parameterRef", parameter), format!("{what}: parameter `{parameter}` is not declared by the scenario")));
                }
                ValueCondition::Variable { variable, .. } if !declares(&s.variables, variable) => {
                    out.push(problem(&at(&c.origin, "variableRef", variable), format!("{what}: variable `{variable}` is not declared by the scenario")));
                }
                ValueCondition::StoryboardElementState { element_type, element, .. } => {
                    if let Err(storyboard::Unresolved::None(message)) = elements.resolve(*element_type, element) {
                        out.push(problem(&at(&c.origin, "storyboardElementRef", element), format!("{what}: {message}")));
                    }
                }
                ValueCondition::TrafficSignalController { controller, .. } => {
                    signal_controller(controller, &c.origin, "trafficSignalControllerRef", what, &mut out);
                }
                _ => {}
            },
            ConditionKind::Unsupported { .. } => {}
        }
    });
    for (p, within) in positions(s) {
        if let Some(name) = p.reference_entity() {
            entity(name, within, "entityRef", "position relative to entity", &mut out);
        }
        if let Position::Route { in_route: InRoutePosition::FromCurrentEntity { entity: name }, .. } = p {
            entity(name, within, "entityRef", "route position of entity", &mut out);
        }
    }
    out
}

/// Storyboard element references that name several elements (esmini takes the first), as
/// warnings at their attributes, each place once.
pub fn ambiguous(s: &Scenario) -> Vec<Diagnostic> {
    let elements = storyboard::Elements::of(s);
    let mut out: Vec<Diagnostic> = Vec::new();
    for_each_condition(s, |c| {
        if let ConditionKind::ByValue(ValueCondition::StoryboardElementState { element_type, element, .. }) = &c.kind {
            if let Err(storyboard::Unresolved::Several(message)) = elements.resolve(*element_type, element) {
                let w = problem(s.reference_site(&c.origin, "storyboardElementRef", |v| v == element), format!("{}: {message}", c.kind.element_name()));
                if !out.contains(&w) {
                    out.push(w);
                }
            }
        }
    });
    out
}

/// A maneuver group whose maneuvers hold private actions but that names no actor (and does not
/// take the triggering entities as its actors): those actions act on nothing. The standard makes
/// the actors of a maneuver group the entities its private actions act on.
fn actorless_private_actions(mg: &ManeuverGroup) -> Option<Diagnostic> {
    if !mg.actors.is_empty() || mg.select_triggering_entities {
        return None;
    }
    let first = mg.maneuvers.iter().flat_map(|m| &m.events).flat_map(|e| &e.actions).find(|a| matches!(a.kind, ActionKind::Private(_)))?;
    Some(problem(
        &mg.origin,
        format!(
            "maneuver group `{}` has private actions (the first, {}, at line {}) but no actor: they act on no entity",
            mg.name,
            first.kind.element_name(),
            first.origin.line
        ),
    ))
}

fn problem(at: &Location, message: String) -> Diagnostic {
    Diagnostic { location: at.clone(), message }
}

fn declares(decls: &[crate::ParameterDeclaration], name: &str) -> bool {
    let name = name.trim_start_matches('$');
    decls.iter().any(|d| d.name == name)
}

/// Inline trailers are entities too (the run names them after their tow vehicle, `<tow>+`).
fn declare_entity<'a>(e: &'a Entity, names: &mut BTreeSet<&'a str>, depth: usize) {
    names.insert(e.name.as_str());
    if depth < 8 {
        if let EntityObject::Vehicle(Vehicle { trailer: Some(Trailer::Entity(t)), .. }) = &e.object {
            declare_entity(t, names, depth + 1);
        }
    }
}

/// Entities an action names besides its actors, with the attribute that names each.
fn action_entities(kind: &ActionKind) -> Vec<(&'static str, &str)> {
    match kind {
        ActionKind::Private(p) => match p {
            PrivateAction::Speed { target: SpeedTarget::Relative { entity, .. }, .. }
            | PrivateAction::LongitudinalDistance { entity, .. }
            | PrivateAction::LateralDistance { entity, .. }
            | PrivateAction::LaneChange { target: LaneChangeTarget::Relative { entity, .. }, .. }
            | PrivateAction::LaneOffset { target: LaneOffsetTarget::Relative { entity, .. }, .. } => vec![("entityRef", entity)],
            PrivateAction::SpeedProfile { entity: Some(entity), .. } => vec![("entityRef", entity)],
            PrivateAction::Synchronize { master, .. } => vec![("masterEntityRef", master)],
            PrivateAction::ConnectTrailer { trailer } => vec![("trailerRef", trailer)],
            _ => vec![],
        },
        ActionKind::Global(g) => match g {
            GlobalAction::AddEntity { entity, .. } | GlobalAction::DeleteEntity { entity } => vec![("entityRef", entity)],
            GlobalAction::TrafficSwarm { central_entity, .. } => vec![("entityRef", central_entity)],
            _ => vec![],
        },
        _ => vec![],
    }
}

/// Entities a condition measures against besides its triggering entities.
fn condition_entities(c: &EntityCondition) -> Vec<&str> {
    match c {
        EntityCondition::TimeHeadway { entity, .. }
        | EntityCondition::RelativeSpeed { entity, .. }
        | EntityCondition::RelativeDistance { entity, .. }
        | EntityCondition::RelativeAngle { entity, .. } => vec![entity],
        EntityCondition::Collision { target: CollisionTarget::Entity(entity) } => vec![entity],
        EntityCondition::TimeToCollision { target: TtcTarget::Entity(entity), .. } => vec![entity],
        EntityCondition::RelativeClearance { entities, .. } => entities.iter().map(String::as_str).collect(),
        _ => vec![],
    }
}

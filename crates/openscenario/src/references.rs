//! Names that must refer to something the scenario declares: entities (Init, actors, actions,
//! conditions, positions), storyboard elements, global parameters and variables, traffic
//! signal controllers. A name that refers to nothing is a *problem*: the caller decides whether
//! it stops the file (osc2cr's default) or is reported and passed over (`--lenient`).
//!
//! Roads and lanes are checked where the road network is loaded (`engine::road_references`);
//! catalogs, catalog entries and `$parameter` expressions are resolved, and fail, while reading.

use std::collections::BTreeSet;

use crate::error::{Location, Warning};
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

/// Every name of the scenario that refers to nothing it declares, as a positioned problem.
pub fn unresolved(s: &Scenario) -> Vec<Warning> {
    let mut entities = BTreeSet::new();
    for e in &s.entities {
        declare_entity(e, &mut entities, 0);
    }
    for sel in &s.entity_selections {
        entities.insert(sel.name.as_str());
    }
    let elements = storyboard_elements(s);
    let mut out = Vec::new();
    let entity = |name: &str, at: &Location, what: &str, out: &mut Vec<Warning>| {
        if !entities.contains(name) {
            out.push(problem(at, format!("{what} `{name}` is not an entity of the scenario")));
        }
    };

    for p in &s.storyboard.init.private {
        let at = p.actions.first().map(|a| &a.origin);
        if let Some(at) = at {
            entity(&p.entity, at, "Init actions for entity", &mut out);
        }
    }
    for story in &s.storyboard.stories {
        for act in &story.acts {
            for mg in &act.maneuver_groups {
                for a in &mg.actors {
                    entity(a, &mg.origin, &format!("actor of maneuver group `{}`:", mg.name), &mut out);
                }
            }
        }
    }
    for_each_action(s, |a, _| {
        let what = a.kind.element_name();
        for name in action_entities(&a.kind) {
            entity(name, &a.origin, &format!("{what}: entity"), &mut out);
        }
        match &a.kind {
            ActionKind::Global(GlobalAction::ParameterSet { parameter, .. }) | ActionKind::Global(GlobalAction::ParameterModify { parameter, .. })
                if s.parameter(parameter).is_none() =>
            {
                out.push(problem(&a.origin, format!("{what}: parameter `{parameter}` is not declared by the scenario")));
            }
            ActionKind::Global(GlobalAction::VariableSet { variable, .. }) | ActionKind::Global(GlobalAction::VariableModify { variable, .. })
                if !declares(&s.variables, variable) =>
            {
                out.push(problem(&a.origin, format!("{what}: variable `{variable}` is not declared by the scenario")));
            }
            ActionKind::Global(GlobalAction::TrafficSignalController { controller, .. })
                if !s.road_network.traffic_signal_controllers.iter().any(|c| &c.name == controller) =>
            {
                out.push(problem(&a.origin, format!("{what}: traffic signal controller `{controller}` is not declared in the RoadNetwork")));
            }
            _ => {}
        }
    });
    for_each_condition(s, |c| {
        let what = c.kind.element_name();
        match &c.kind {
            ConditionKind::ByEntity { entities: triggering, condition, .. } => {
                for name in triggering {
                    entity(name, &c.origin, &format!("{what}: triggering entity"), &mut out);
                }
                for name in condition_entities(condition) {
                    entity(name, &c.origin, &format!("{what}: entity"), &mut out);
                }
            }
            ConditionKind::ByValue(v) => match v {
                ValueCondition::Parameter { parameter, .. } if s.parameter(parameter).is_none() => {
                    out.push(problem(&c.origin, format!("{what}: parameter `{parameter}` is not declared by the scenario")));
                }
                ValueCondition::Variable { variable, .. } if !declares(&s.variables, variable) => {
                    out.push(problem(&c.origin, format!("{what}: variable `{variable}` is not declared by the scenario")));
                }
                ValueCondition::StoryboardElementState { element_type, element, .. } => {
                    // esmini finds an element by its own name or by a `::`-separated path
                    let own = element.rsplit("::").next().unwrap_or(element);
                    if !elements.contains(&(*element_type, own)) {
                        out.push(problem(&c.origin, format!("{what}: there is no {} named `{element}` in the storyboard", element_type)));
                    }
                }
                ValueCondition::TrafficSignalController { controller, .. }
                    if !s.road_network.traffic_signal_controllers.iter().any(|t| &t.name == controller) =>
                {
                    out.push(problem(&c.origin, format!("{what}: traffic signal controller `{controller}` is not declared in the RoadNetwork")));
                }
                _ => {}
            },
            ConditionKind::Unsupported { .. } => {}
        }
    });
    for (p, at) in positions(s) {
        if let Some(name) = p.reference_entity() {
            entity(name, at, "position relative to entity", &mut out);
        }
        if let Position::Route { in_route: InRoutePosition::FromCurrentEntity { entity: name }, .. } = p {
            entity(name, at, "route position of entity", &mut out);
        }
    }
    out
}

fn problem(at: &Location, message: String) -> Warning {
    Warning { location: at.clone(), message }
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

/// Entities an action names besides its actors.
fn action_entities(kind: &ActionKind) -> Vec<&str> {
    match kind {
        ActionKind::Private(p) => match p {
            PrivateAction::Speed { target: SpeedTarget::Relative { entity, .. }, .. }
            | PrivateAction::LongitudinalDistance { entity, .. }
            | PrivateAction::LateralDistance { entity, .. }
            | PrivateAction::LaneChange { target: LaneChangeTarget::Relative { entity, .. }, .. }
            | PrivateAction::LaneOffset { target: LaneOffsetTarget::Relative { entity, .. }, .. } => vec![entity],
            PrivateAction::SpeedProfile { entity: Some(entity), .. } => vec![entity],
            PrivateAction::Synchronize { master, .. } => vec![master],
            PrivateAction::ConnectTrailer { trailer } => vec![trailer],
            _ => vec![],
        },
        ActionKind::Global(g) => match g {
            GlobalAction::AddEntity { entity, .. } | GlobalAction::DeleteEntity { entity } => vec![entity],
            GlobalAction::TrafficSwarm { central_entity, .. } => vec![central_entity],
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

/// (type, name) of every named storyboard element.
fn storyboard_elements(s: &Scenario) -> BTreeSet<(StoryboardElementType, &str)> {
    use StoryboardElementType as T;
    let mut out = BTreeSet::new();
    for story in &s.storyboard.stories {
        out.insert((T::Story, story.name.as_str()));
        for act in &story.acts {
            out.insert((T::Act, act.name.as_str()));
            for mg in &act.maneuver_groups {
                out.insert((T::ManeuverGroup, mg.name.as_str()));
                for m in &mg.maneuvers {
                    out.insert((T::Maneuver, m.name.as_str()));
                    for e in &m.events {
                        out.insert((T::Event, e.name.as_str()));
                        for a in &e.actions {
                            out.insert((T::Action, a.name.as_str()));
                        }
                    }
                }
            }
        }
    }
    out
}

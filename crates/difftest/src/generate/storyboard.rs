//! One scenario put together: the entities (one to three vehicles — cars, trucks, bicycles,
//! some parked facing either way, some reversing — and maybe a pedestrian, a misc object and
//! a trailer), their Init (a position of any type, a speed, a route, a driver model), a story
//! of one to four events (private or global actions, each started by a trigger, with a
//! priority and an execution count) and a stop trigger; then the document, in the 1.3
//! schema's order.

use std::fmt::Write as _;

use super::controllers::TYPES;
use super::lanes::{lanes_at, Place};
use super::positions::Scope;
use super::{Area, EntityKind, EntityPlan, Gen};

impl Gen<'_> {
    /// The kinds of the scenario's entities, in order (the first is a car).
    fn cast(&mut self) -> Vec<EntityKind> {
        let vehicles = self.rng_range(1, 3);
        let mut kinds = vec![EntityKind::Car];
        if !self.rich(Area::RoadUsers) {
            kinds.extend((1..vehicles).map(|_| EntityKind::Car));
            return kinds;
        }
        for _ in 1..vehicles {
            kinds.push(self.pick(&[EntityKind::Car, EntityKind::Car, EntityKind::Truck, EntityKind::Bicycle]));
        }
        if self.chance(0.45) {
            kinds.push(EntityKind::Pedestrian);
        }
        if self.chance(0.45) {
            kinds.push(EntityKind::Misc);
        }
        if self.chance(0.15) {
            kinds.push(EntityKind::Trailer);
        }
        kinds
    }

    fn rng_range(&mut self, lo: usize, hi: usize) -> usize {
        lo + self.pick_index(hi - lo + 1)
    }

    /// A place for entity `k` of `kind` placed absolutely: the first anywhere, a later one near
    /// the first (same road) or anywhere; a pedestrian on a sidewalk where the map has them.
    fn absolute_place(&mut self, kind: EntityKind) -> Place {
        if kind == EntityKind::Pedestrian {
            let walks: Vec<_> = self.map.spots.iter().filter(|s| s.sidewalk).cloned().collect();
            if !walks.is_empty() && self.chance(0.7) {
                self.feature("pedestrian:sidewalk");
                let w = walks[self.pick_index(walks.len())].clone();
                return Place { road: w.road, lane: w.lane, s: self.num(w.s_min, w.s_max.max(w.s_min + 0.01)), forward: w.along_s };
            }
        }
        if let Some(first) = self.entities.first().and_then(|e| e.place) {
            if self.chance(0.5) {
                let len = self.map.net.roads.get(first.road).map_or(0.0, |r| r.length);
                let s = (first.s + self.num(-60.0, 60.0)).clamp(1.0, (len - 1.0).max(1.0));
                let lanes = lanes_at(&self.map.net, first.road, s);
                if !lanes.is_empty() {
                    let (lane, forward) = lanes[self.pick_index(lanes.len())];
                    return Place { road: first.road, lane, s, forward };
                }
            }
        }
        self.random_place()
    }

    /// The Init actions of entity `name` of `kind`; its plan is pushed to `self.entities`.
    fn init_entity(&mut self, name: &str, kind: EntityKind, controller: Option<String>) -> String {
        let parked = match kind {
            EntityKind::Misc | EntityKind::Trailer => true,
            EntityKind::Car | EntityKind::Truck => self.rich(Area::RoadUsers) && self.chance(0.25),
            _ => false,
        };
        let facing_back = parked && self.chance(0.5);
        if parked && kind != EntityKind::Trailer {
            self.feature(format!("parked:{}/facing-{}", kind.label(), if facing_back { "against" } else { "along" }));
        }
        let mut actions = String::new();
        let (position, place) = if kind == EntityKind::Trailer {
            let towing = self.entities.iter().find(|e| e.kind == EntityKind::Car).map(|e| e.name.clone()).unwrap_or_default();
            (format!(r#"<RelativeObjectPosition entityRef="{towing}" dx="-6.5" dy="0"/>"#), None)
        } else if self.entities.is_empty() || self.chance(0.35) {
            let p = self.absolute_place(kind);
            (self.place_position(&p, "init:", Scope::Any, facing_back), Some(p))
        } else {
            let placed: Vec<(String, Option<Place>)> =
                self.entities.iter().filter(|e| e.kind != EntityKind::Trailer).map(|e| (e.name.clone(), e.place)).collect();
            let (reference, at) = placed[self.pick_index(placed.len())].clone();
            self.relative_position(&reference, at, "init:")
        };
        let _ = write!(actions, "<PrivateAction><TeleportAction><Position>{position}</Position></TeleportAction></PrivateAction>");
        let speed = match kind {
            _ if parked => 0.0,
            EntityKind::Pedestrian => self.num(0.5, 2.5),
            EntityKind::Bicycle => self.num(2.0, 8.0),
            _ if self.rich(Area::Longitudinal) && self.chance(0.12) => {
                self.feature("init:speed-negative");
                self.num(-6.0, -0.5)
            }
            _ => self.num(0.0, 30.0),
        };
        if kind != EntityKind::Misc && kind != EntityKind::Trailer {
            let _ = write!(
                actions,
                r#"<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="step" value="0" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="{speed}"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>"#
            );
        }
        self.entities.push(EntityPlan { name: name.to_string(), kind, place, speed, controller: controller.clone() });
        let needs_route = controller.as_deref() == Some("FollowRouteController");
        if place.is_some() && (needs_route || (!parked && kind != EntityKind::Pedestrian && self.rich(Area::Routes) && self.chance(0.4))) {
            self.feature("init:AssignRouteAction");
            actions.push_str(&self.assign_route_action(name));
        }
        if controller.is_some() && (!self.rich(Area::Controllers) || self.chance(0.6)) {
            self.feature("controller:activated-in-init");
            let kind = controller.clone().unwrap_or_default();
            actions.push_str(&self.activate_controller_action(name, &kind));
        }
        actions
    }

    /// One event of the story, number `k`.
    fn event(&mut self, k: usize, pending_activation: &mut Vec<String>) -> String {
        self.current_event = k;
        self.forced_condition = None;
        let mobile = self.mobile_names();
        let global = (self.rich(Area::Globals) && self.chance(0.4)) || mobile.is_empty();
        let t_start = self.num(0.0, 6.0);
        let (actors, action, actor) = if global {
            (String::new(), self.global_action(), mobile.first().cloned().unwrap_or_default())
        } else {
            let actor = mobile[self.pick_index(mobile.len())].clone();
            let action = if let Some(i) = pending_activation.iter().position(|n| *n == actor) {
                pending_activation.remove(i);
                self.feature("controller:activated-in-story");
                self.feature("action:ActivateControllerAction");
                let kind = self.entity(&actor).and_then(|e| e.controller.clone()).unwrap_or_default();
                self.activate_controller_action(&actor, &kind)
            } else if self.rich(Area::Controllers) && self.entity(&actor).is_some_and(|e| e.vehicle() && e.controller.is_none()) && self.chance(0.15) {
                // (the override's draw only in this branch: other scenarios keep their bytes)
                if self.chance(0.3) {
                    self.override_controller_value_action()
                } else {
                    self.assign_controller_action(&actor)
                }
            } else {
                self.private_action(&actor, t_start)
            };
            (format!(r#"<EntityRef entityRef="{actor}"/>"#), action, actor)
        };
        let trigger = self.trigger("StartTrigger", &actor);
        let priority = if self.rich(Area::Conditions) {
            self.pick(&["parallel", "parallel", "override", "skip"])
        } else {
            self.pick(&["parallel", "parallel", "override"])
        };
        let priority = self.priority_word(priority);
        if priority != "parallel" {
            self.feature(format!("priority:{priority}"));
        }
        let count = if self.rich(Area::Conditions) && self.chance(0.15) {
            self.feature("event:repeated");
            self.rng_range(2, 3)
        } else {
            1
        };
        format!(
            r#"<ManeuverGroup maximumExecutionCount="1" name="G{k}"><Actors selectTriggeringEntities="false">{actors}</Actors>
<Maneuver name="M{k}"><Event name="E{k}" priority="{priority}" maximumExecutionCount="{count}"><Action name="A{k}">{action}</Action>
{trigger}</Event></Maneuver></ManeuverGroup>
"#
        )
    }

    /// The whole scenario.
    pub(crate) fn scenario(&mut self, seed: u64, index: u64) -> String {
        self.feature(format!("map:{}", self.map.label));
        if self.map.label == "folder" {
            let stem = self.map.path.file_stem().map(|s| s.to_string_lossy().to_string()).unwrap_or_default();
            self.feature(format!("map-file:{stem}"));
        }
        if self.map.left_hand {
            self.feature("map:left-hand-traffic");
        }
        let kinds = self.cast();
        let vehicles = kinds.iter().filter(|k| matches!(k, EntityKind::Car | EntityKind::Truck | EntityKind::Bicycle)).count();
        if vehicles > 1 {
            self.feature(format!("entities:{vehicles}"));
        }
        let mut definitions = String::new();
        // each entity's Init actions, in order (esmini takes one Private per entity)
        let mut init: Vec<(String, String)> = Vec::new();
        let mut pending_activation = Vec::new();
        let mut ghost_taken = false;
        self.all_names = kinds
            .iter()
            .enumerate()
            .map(|(i, kind)| match kind {
                EntityKind::Car => format!("Car{i}"),
                EntityKind::Truck => format!("Truck{i}"),
                EntityKind::Bicycle => format!("Bike{i}"),
                EntityKind::Pedestrian => format!("Ped{i}"),
                EntityKind::Misc => format!("Obj{i}"),
                EntityKind::Trailer => format!("Trailer{i}"),
            })
            .collect();
        for (i, kind) in kinds.iter().enumerate() {
            let name = self.all_names[i].clone();
            if *kind != EntityKind::Car {
                self.feature(format!("entity:{}", kind.label()));
            }
            let hitch = i == 0 && kinds.contains(&EntityKind::Trailer);
            let definition = self.entity_definition(*kind, hitch);
            // a driver model for some vehicles (one ghost at most: osc2cr runs one)
            let mut controller = None;
            let mut controller_xml = String::new();
            let rich = self.rich(Area::Controllers);
            if matches!(kind, EntityKind::Car | EntityKind::Truck) && self.chance(if rich { 0.5 } else { 0.2 }) {
                let mut t = if rich { self.pick(&TYPES) } else { "ACCController" };
                if (t == "FollowGhostController" && ghost_taken)
                    || (matches!(t, "FollowReferenceController" | "OffroadFollower") && self.followed(&name).is_none())
                {
                    t = "ACCController";
                }
                ghost_taken |= t == "FollowGhostController";
                let wrapper = self.object_controller_open(&name);
                controller_xml = format!("{wrapper}{}</ObjectController>", self.controller_xml(t, &name));
                controller = Some(t.to_string());
            }
            let _ = write!(definitions, r#"<ScenarioObject name="{name}">{definition}{controller_xml}</ScenarioObject>"#);
            let actions = self.init_entity(&name, *kind, controller.clone());
            if controller.is_some() && !actions.contains("ActivateControllerAction") {
                pending_activation.push(name.clone());
            }
            init.push((name.clone(), actions));
            if *kind == EntityKind::Trailer && self.chance(0.6) {
                let towing = self.entities.iter().find(|e| e.kind == EntityKind::Car).map(|e| e.name.clone()).unwrap_or_default();
                self.feature("trailer:connected-in-init");
                if let Some((_, a)) = init.iter_mut().find(|(n, _)| *n == towing) {
                    let _ = write!(a, r#"<PrivateAction><TrailerAction><ConnectTrailerAction trailerRef="{name}"/></TrailerAction></PrivateAction>"#);
                }
            }
        }

        let events = self.rng_range(1, 4);
        for k in 0..events {
            self.elements.push(("event", format!("E{k}")));
            self.elements.push(("action", format!("A{k}")));
            self.elements.push(("maneuverGroup", format!("G{k}")));
        }
        self.elements.push(("act", "Act".into()));
        let mut groups = String::new();
        for k in 0..events {
            groups.push_str(&self.event(k, &mut pending_activation));
        }
        let groups = self.retarget_dropped_actions(groups);
        let stop = self.num(6.0, 15.0);
        let stop_trigger = format!(
            r#"<StopTrigger><ConditionGroup><Condition name="stop" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="{stop}" rule="greaterThan"/></ByValueCondition></Condition></ConditionGroup></StopTrigger>"#
        );
        let init: String = init.iter().map(|(n, a)| format!("<Private entityRef=\"{n}\">{a}</Private>\n")).collect();
        self.document(seed, index, &definitions, &init, &groups, &stop_trigger)
    }

    /// Turns every StoryboardElementStateCondition on an action esmini drops onto that
    /// action's event (same name number), and names the conditions' features.
    fn retarget_dropped_actions(&mut self, mut groups: String) -> String {
        for k in &self.dropped_actions {
            let on_action = format!(r#"storyboardElementType="action" storyboardElementRef="A{k}""#);
            groups = groups.replace(&on_action, &format!(r#"storyboardElementType="event" storyboardElementRef="E{k}""#));
        }
        for (name, state) in std::mem::take(&mut self.action_state_refs) {
            let dropped = self.dropped_actions.iter().any(|k| name == format!("A{k}"));
            self.feature(format!("storyboard-state:{}/{state}", if dropped { "event" } else { "action" }));
        }
        groups
    }

    fn document(&self, seed: u64, index: u64, entities: &str, init: &str, groups: &str, stop_trigger: &str) -> String {
        let declare = |items: &[super::Declared], outer: &str, inner: &str, type_attr: &str| -> String {
            if items.is_empty() {
                return if outer == "ParameterDeclarations" { "<ParameterDeclarations/>".into() } else { String::new() };
            }
            let body: String = items.iter().map(|d| format!(r#"<{inner} name="{}" {type_attr}="{}" value="{}"/>"#, d.name, d.kind, d.value)).collect();
            format!("<{outer}>{body}</{outer}>")
        };
        let parameters = declare(&self.parameters, "ParameterDeclarations", "ParameterDeclaration", "parameterType");
        let variables = declare(&self.variables, "VariableDeclarations", "VariableDeclaration", "variableType");
        let signals = if self.uses_signals { self.signal_controllers() } else { String::new() };
        format!(
            r#"<?xml version="1.0" encoding="UTF-8"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="{rev_minor}" date="2026-01-01T00:00:00" description="difftest seed {seed} scenario {index}" author="osc2cr difftest"/>
{parameters}{variables}
<CatalogLocations/>
<RoadNetwork><LogicFile filepath="{map}"/>{signals}</RoadNetwork>
<Entities>{entities}</Entities>
<Storyboard>
<Init><Actions>
{init}</Actions></Init>
<Story name="S"><Act name="Act">
{groups}<StartTrigger><ConditionGroup><Condition name="start" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition value="0" rule="{start_rule}"/></ByValueCondition></Condition></ConditionGroup></StartTrigger>
</Act></Story>
{stop_trigger}
</Storyboard>
</OpenSCENARIO>
"#,
            map = self.map.name,
            rev_minor = self.rev_minor,
            start_rule = self.rule_word("greaterOrEqual")
        )
    }
}

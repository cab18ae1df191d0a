//! Building the run state of a scenario: the storyboard flattened into nodes (Init actions
//! in esmini's order, then stories, acts, maneuver groups, maneuvers, events, actions), its
//! triggers, the entities with their controllers, trailers and presence, the ghost of a
//! FollowGhost controller, the entities driven from outside. It sits above the behaviours
//! (it asks each to set up its part); `sim.rs` is the state it fills.

use crate::actions::state::ActionSlot;
use crate::conditions::state::TriggerRt;
use crate::entities::Entity;
use crate::sim::Sim;
use crate::storyboard::{Kind, Node};
use crate::values::Values;
use crate::Diagnostic;
use opendrive::RoadNetwork;
use openscenario::{Action, ActionKind, Scenario, Trigger};

impl<'a> Sim<'a> {
    /// The run state; `Err` when `external` names an entity the scenario does not have.
    pub(crate) fn new(scenario: &'a Scenario, net: Option<&'a RoadNetwork>, dt: f64, external: &crate::external::External) -> Result<Sim<'a>, String> {
        let mut sim = Sim {
            scenario,
            net,
            dt,
            time: 0.0,
            clock: 0.0,
            entities: Entity::from_scenario(scenario),
            nodes: Vec::new(),
            triggers: Vec::new(),
            actions: Vec::new(),
            init_actions: Vec::new(),
            params: Values::from_declarations(&scenario.parameters),
            vars: Values::from_declarations(&scenario.variables),
            events: Vec::new(),
            state_log: Vec::new(),
            warnings: Vec::new(),
            controllers: Vec::new(),
            any_controller: false,
            assignments: 0,
            trailers: Default::default(),
            ghost: None,
            triggering_actors: Vec::new(),
            lights: Vec::new(),
            environment: Vec::new(),
            signals: Default::default(),
            random: Default::default(),
            external_choice: external.clone(),
            external: vec![None; scenario.entities.len()],
            nd_distances: Default::default(),
        };
        sim.signals = crate::signals::Signals::new(scenario, net, &mut sim.warnings);
        sim.trailers = crate::actions::trailer::state::Trailers::build(scenario, &mut sim.entities);
        sim.initial_presence();
        for (i, e) in scenario.entities.iter().enumerate() {
            for c in &e.controllers {
                sim.assign_controller(i, c, &c.name, None);
            }
        }
        sim.name_external(external)?;
        sim.build();
        sim.setup_ghost();
        Ok(sim)
    }

    fn push_node(&mut self, node: Node) -> usize {
        let id = self.nodes.len();
        if let Some(p) = node.parent {
            if let Some(pn) = self.nodes.get_mut(p) {
                pn.children.push(id);
            }
        }
        self.nodes.push(node);
        id
    }

    fn add_trigger(&mut self, t: Option<&'a Trigger>, start: bool) -> Option<usize> {
        let t = t?;
        // An empty start trigger behaves as none (esmini starts the element at once).
        if start && t.groups.is_empty() {
            return None;
        }
        for c in t.groups.iter().flat_map(|g| &g.conditions) {
            if let openscenario::ConditionKind::ByValue(v) = &c.kind {
                if let Some(why) = crate::conditions::by_value::ignored_by_esmini(v) {
                    let msg = format!(
                        "condition `{}`: {} is left out of its condition group, as esmini 3.6.0 does ({why}); a group with nothing else never holds",
                        c.name,
                        v.element_name()
                    );
                    self.warnings.push(Diagnostic::at(&c.origin, msg));
                }
            }
        }
        let rt = TriggerRt::new(t, self);
        self.triggers.push(rt);
        Some(self.triggers.len() - 1)
    }

    fn add_action(&mut self, action: &'a Action, name: &str, parent: Option<usize>, actors: Vec<usize>) -> usize {
        let node = self.push_node(Node::new(Kind::Action, name, parent));
        let slot = ActionSlot::new(node, action, actors);
        self.actions.push(slot);
        let idx = self.actions.len() - 1;
        if let Some(n) = self.nodes.get_mut(node) {
            n.action = Some(idx);
        }
        idx
    }

    fn build(&mut self) {
        let sc = self.scenario;
        let sb = &sc.storyboard;
        let root = self.push_node(Node::new(Kind::Storyboard, "storyBoard", None));
        let stop = self.add_trigger(sb.stop_trigger.as_ref(), false);
        self.nodes[root].stop_trigger = stop;
        for a in &sb.init.global {
            let name = format!("Init {}", a.kind.element_name());
            let slot = self.add_action(a, &name, None, Vec::new());
            self.init_actions.push(slot);
        }
        // esmini runs Init private actions in an order where relative teleports follow their
        // reference entity's actions (init_order.rs)
        let mut items = Vec::new();
        let mut actions = Vec::new();
        for p in &sb.init.private {
            let Some(entity) = self.entity_index(&p.entity) else {
                self.warnings.push(Diagnostic::at(
                    &sc.entities.first().map(|e| e.origin.clone()).unwrap_or_else(|| sb_origin(sc)),
                    format!("Init actions for unknown entity `{}` ignored", p.entity),
                ));
                continue;
            };
            for a in &p.actions {
                let relative_to = crate::init_order::teleport_reference(&a.kind).and_then(|r| self.entity_index(r));
                items.push(crate::init_order::InitItem { entity, relative_to, index: actions.len() });
                actions.push((entity, p.entity.as_str(), a));
            }
        }
        if crate::init_order::reorder(&mut items) {
            self.warnings.push(Diagnostic::at(
                &sb_origin(sc),
                "Init actions: teleports relative to each other in a circle; esmini gives up reordering them after 2n passes, and so does osc2cr",
            ));
        }
        let order = items.iter().map(|i| i.index);
        for k in order {
            let Some(&(entity, name, a)) = actions.get(k) else { continue };
            let name = format!("Init {} {}", name, a.kind.element_name());
            let slot = self.add_action(a, &name, None, vec![entity]);
            self.init_actions.push(slot);
        }
        for story in &sb.stories {
            let sn = self.push_node(Node::new(Kind::Story, &story.name, Some(root)));
            for act in &story.acts {
                let an = self.push_node(Node::new(Kind::Act, &act.name, Some(sn)));
                let st = self.add_trigger(act.start_trigger.as_ref(), true);
                let sp = self.add_trigger(act.stop_trigger.as_ref(), false);
                self.nodes[an].start_trigger = st;
                self.nodes[an].stop_trigger = sp;
                for mg in &act.maneuver_groups {
                    let mut node = Node::new(Kind::ManeuverGroup, &mg.name, Some(an));
                    node.max_executions = mg.maximum_execution_count.max(1);
                    let gn = self.push_node(node);
                    let mut actors = Vec::new();
                    for a in &mg.actors {
                        match self.entity_index(a) {
                            Some(i) => actors.push(i),
                            None => {
                                let expanded = self.selection_members(a);
                                if expanded.is_empty() {
                                    self.warnings
                                        .push(Diagnostic::at(&mg.origin, format!("actor `{a}` of maneuver group `{}` is not an entity; ignored", mg.name)));
                                }
                                actors.extend(expanded);
                            }
                        }
                    }
                    let first_slot = self.actions.len();
                    for m in &mg.maneuvers {
                        let mn = self.push_node(Node::new(Kind::Maneuver, &m.name, Some(gn)));
                        for ev in &m.events {
                            let mut node = Node::new(Kind::Event, &ev.name, Some(mn));
                            node.max_executions = ev.maximum_execution_count.max(1);
                            node.priority = ev.priority;
                            let en = self.push_node(node);
                            let st = self.add_trigger(ev.start_trigger.as_ref(), true);
                            self.nodes[en].start_trigger = st;
                            for a in &ev.actions {
                                let private = matches!(a.kind, ActionKind::Private(_));
                                let actors = if private { actors.clone() } else { Vec::new() };
                                self.add_action(a, &a.name, Some(en), actors);
                            }
                        }
                    }
                    if mg.select_triggering_entities {
                        let slots = (first_slot..self.actions.len()).filter(|&k| matches!(self.actions[k].model.kind, ActionKind::Private(_))).collect();
                        self.triggering_actors.push(crate::storyboard::tree::TriggeringActors { group: gn, listed: actors, slots });
                    }
                }
            }
        }
        // Resolve element references of StoryboardElementState conditions now that every node exists.
        let nodes = &self.nodes;
        for t in &mut self.triggers {
            t.resolve_elements(nodes);
        }
    }

    fn selection_members(&self, name: &str) -> Vec<usize> {
        let mut out = Vec::new();
        if let Some(sel) = self.scenario.entity_selections.iter().find(|s| s.name == name) {
            for m in &sel.members {
                match m {
                    openscenario::SelectionMember::Entity(n) => out.extend(self.entity_index(n)),
                    openscenario::SelectionMember::ByType(_) => {}
                }
            }
        }
        out
    }
}

fn sb_origin(sc: &Scenario) -> openscenario::Origin {
    openscenario::Origin { file: std::sync::Arc::from(sc.path.as_path()), line: 0, col: 0 }
}

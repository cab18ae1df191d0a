//! Triggers at run time: an OR over condition groups, each an AND over conditions; every
//! condition with its edge detection and delay, as esmini evaluates them (a group stops
//! evaluating after its first false condition unless a later one has a delay; a rising or
//! falling edge needs one evaluation before it can fire; a fired trigger re-arms its edges).

pub(crate) mod boxes;
pub(crate) mod by_entity;
pub(crate) mod by_value;
pub(crate) mod clearance;
pub(crate) mod distance;
pub(crate) mod free_space;
pub(crate) mod reach_orientation;
pub(crate) mod state;
pub(crate) mod traffic_signal;
pub(crate) mod triggering;

use self::state::{ConditionRt, TriggerRt};
use crate::sim::Sim;
use crate::storyboard::{Kind, Node};
use openscenario::{Condition, ConditionEdge, ConditionKind, EntityCondition, StoryboardElementType, Trigger, ValueCondition};

impl<'a> TriggerRt<'a> {
    pub(crate) fn new(t: &'a Trigger, sim: &Sim) -> TriggerRt<'a> {
        let kept = |c: &&Condition| !matches!(&c.kind, ConditionKind::ByValue(v) if by_value::ignored_by_esmini(v).is_some());
        let groups = t.groups.iter().map(|g| g.conditions.iter().filter(kept).map(|c| ConditionRt::new(c, sim)).collect()).collect();
        TriggerRt { groups }
    }

    /// Back to fresh for another execution (esmini's Trigger::Reset). A StoryboardElementState
    /// condition also forgets the state changes logged so far and not yet evaluated
    /// (TrigByState::Reset clears its list; the latest state it saw stays): `logged` is the
    /// length of the run's state log now.
    pub(crate) fn reset(&mut self, logged: usize) {
        for g in &mut self.groups {
            for c in g {
                c.history.clear();
                c.value = false;
                c.cursor = c.cursor.max(logged);
            }
        }
    }

    pub(crate) fn resolve_elements(&mut self, nodes: &[Node]) {
        for g in &mut self.groups {
            for c in g {
                if let ConditionKind::ByValue(ValueCondition::StoryboardElementState { element_type, element, .. }) = &c.model.kind {
                    c.element = find_element(nodes, *element_type, element);
                }
            }
        }
    }
}

/// The node named `name` (possibly a `a::b::c` path, matched on its last part) of a kind.
fn find_element(nodes: &[Node], kind: StoryboardElementType, name: &str) -> Option<usize> {
    let want = match kind {
        StoryboardElementType::Story => Kind::Story,
        StoryboardElementType::Act => Kind::Act,
        StoryboardElementType::ManeuverGroup => Kind::ManeuverGroup,
        StoryboardElementType::Maneuver => Kind::Maneuver,
        StoryboardElementType::Event => Kind::Event,
        StoryboardElementType::Action => Kind::Action,
    };
    let mut parts: Vec<&str> = name.split("::").collect();
    let last = parts.pop().unwrap_or(name);
    let candidates = || nodes.iter().enumerate().filter(|(_, n)| n.kind == want && n.name == last).map(|(i, _)| i);
    // A qualified name ("Event::Action") picks the element whose ancestors carry the leading parts, in
    // order (levels may be skipped); names are often reused ("Action") in different events.
    candidates().find(|&i| ancestors_match(nodes, i, &parts)).or_else(|| candidates().next())
}

/// Whether the ancestors of node `i`, walking up, contain `parts` in reverse order.
fn ancestors_match(nodes: &[Node], i: usize, parts: &[&str]) -> bool {
    let mut want = parts.iter().rev();
    let mut next = want.next();
    let mut cur = nodes.get(i).and_then(|n| n.parent);
    let mut guard = 0;
    while let (Some(p), Some(w)) = (cur, next) {
        guard += 1;
        if guard > 64 {
            break;
        }
        let Some(node) = nodes.get(p) else { break };
        if node.name == *w {
            next = want.next();
        }
        cur = node.parent;
    }
    next.is_none()
}

impl<'a> ConditionRt<'a> {
    fn new(model: &'a Condition, sim: &Sim) -> ConditionRt<'a> {
        let mut triggering = Vec::new();
        let mut other = None;
        if let ConditionKind::ByEntity { entities, condition, .. } = &model.kind {
            for e in entities {
                if let Some(i) = sim.entity_index(e) {
                    triggering.push(i);
                }
            }
            let other_name = match condition {
                EntityCondition::TimeHeadway { entity, .. }
                | EntityCondition::RelativeSpeed { entity, .. }
                | EntityCondition::RelativeDistance { entity, .. } => Some(entity.as_str()),
                EntityCondition::TimeToCollision { target: openscenario::TtcTarget::Entity(e), .. } => Some(e.as_str()),
                EntityCondition::Collision { target: openscenario::CollisionTarget::Entity(e) } => Some(e.as_str()),
                _ => None,
            };
            other = other_name.and_then(|n| sim.entity_index(n));
        }
        ConditionRt {
            model,
            last_result: false,
            evaluated: false,
            value: false,
            history: Vec::new(),
            triggering,
            time_shift: 0.0,
            fired_by: Vec::new(),
            hits: Vec::new(),
            other,
            element: None,
            cursor: 0,
            latest: None,
            warned: false,
        }
    }
}

impl<'a> Sim<'a> {
    /// Evaluate trigger `t` at the current time.
    pub(crate) fn eval_trigger(&mut self, t: usize, _start: bool) -> bool {
        let Some(slot) = self.triggers.get_mut(t) else { return false };
        let mut trig = std::mem::take(slot);
        let mut result = false;
        for g in &mut trig.groups {
            if g.is_empty() {
                continue;
            }
            let mut all = true;
            for c in g.iter_mut() {
                if all || c.model.delay > 0.0 {
                    all &= self.eval_condition(c);
                }
            }
            result |= all;
        }
        if result {
            for g in &mut trig.groups {
                for c in g {
                    c.evaluated = false;
                }
            }
        }
        self.triggers[t] = trig;
        result
    }

    fn eval_condition(&mut self, c: &mut ConditionRt<'a>) -> bool {
        let raw = self.check_condition(c);
        let edged = match c.model.edge {
            ConditionEdge::None => raw,
            _ if !c.evaluated => false,
            ConditionEdge::Rising => raw && !c.last_result,
            ConditionEdge::Falling => !raw && c.last_result,
            ConditionEdge::RisingOrFalling => raw != c.last_result,
        };
        c.last_result = raw;
        c.evaluated = true;
        if c.history.last().is_none_or(|&(_, v)| v != edged) {
            c.history.push((self.time, edged));
        }
        let at = self.time - c.model.delay + 1e-6;
        c.value = c.history.iter().rev().find(|(t, _)| *t <= at).is_some_and(|&(_, v)| v);
        c.value
    }

    fn check_condition(&mut self, c: &mut ConditionRt<'a>) -> bool {
        match &c.model.kind {
            ConditionKind::ByValue(v) => self.check_value(c, v),
            ConditionKind::ByEntity { rule, condition, .. } => self.check_entity(c, *rule, condition),
            ConditionKind::Unsupported { element } => {
                if !c.warned {
                    c.warned = true;
                    let w = crate::Diagnostic::at(&c.model.origin, format!("condition `{}`: {element} is not supported; it never becomes true", c.model.name));
                    self.warnings.push(w);
                }
                false
            }
        }
    }
}

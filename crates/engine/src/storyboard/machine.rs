//! Element transitions, as esmini runs them: a start moves an element from init to standby
//! (it has a start trigger) or to running (it has none) and starts its children; an end moves
//! it to complete, or back to standby while executions remain (maneuver groups, events); a
//! stop completes it and its children; a parent ends when all its children are complete
//! (except the storyboard, which only its stop trigger ends).

use super::tree::{Kind, State, Transition};
use crate::sim::Sim;
use openscenario::Priority;

impl<'a> Sim<'a> {
    /// Start element `id` (the generic rules; events go through [`Sim::start_event`]).
    pub(crate) fn start_element(&mut self, id: usize) {
        let Some(n) = self.nodes.get(id) else { return };
        let (state, has_trigger, kind) = (n.state, n.start_trigger.is_some(), n.kind);
        if state == State::Init && has_trigger {
            self.set_state(id, Transition::InitToStandby, State::Standby);
        } else if state == State::Init || state == State::Standby || self.nodes[id].executions != 0 {
            self.set_state(id, Transition::Start, State::Running);
            self.nodes[id].executions += 1;
            if kind == Kind::ManeuverGroup && !self.triggering_actors.is_empty() {
                self.select_triggering_actors(id);
            }
        }
        if kind != Kind::Event && kind != Kind::Action && self.nodes[id].state == State::Running {
            let children = self.nodes[id].children.clone();
            for c in children {
                if self.nodes[c].kind == Kind::Event {
                    self.start_event(c);
                } else {
                    self.start_element(c);
                }
            }
        }
    }

    /// Start an event, honouring its priority, then start its actions.
    pub(crate) fn start_event(&mut self, id: usize) {
        let Some(n) = self.nodes.get(id) else { return };
        let Some(parent) = n.parent else { return };
        // Going from init to standby involves no priority rules.
        if n.state == State::Init && n.start_trigger.is_some() {
            self.set_state(id, Transition::InitToStandby, State::Standby);
            return;
        }
        let siblings = self.nodes[parent].children.clone();
        let running = |s: &Sim, c: usize| s.nodes.get(c).is_some_and(|n| n.state == State::Running);
        match self.nodes[id].priority {
            Priority::Override => {
                if running(self, id) {
                    return;
                }
                for &c in &siblings {
                    if c != id && running(self, c) {
                        self.end_element(c);
                    }
                }
            }
            Priority::Skip => {
                if siblings.iter().any(|&c| running(self, c)) {
                    return;
                }
            }
            Priority::Parallel => {
                if running(self, id) {
                    return;
                }
            }
        }
        self.set_state(id, Transition::Start, State::Running);
        self.nodes[id].executions += 1;
        let children = self.nodes[id].children.clone();
        if children.is_empty() {
            self.end_element(id);
            return;
        }
        self.ghost_event_starts(id);
        for c in children {
            if let Some(slot) = self.nodes[c].action {
                self.end_conflicting_actions(slot);
                self.start_action(slot);
            }
        }
        self.ghost_event_started();
    }

    /// End element `id`: complete, or standby again while it has executions left.
    pub(crate) fn end_element(&mut self, id: usize) {
        let Some(n) = self.nodes.get(id) else { return };
        if n.state == State::Complete {
            return;
        }
        let children = n.children.clone();
        for c in children {
            if self.nodes[c].state == State::Running {
                self.end_element(c);
            }
        }
        let n = &self.nodes[id];
        if n.state == State::Complete {
            return;
        }
        if n.state == State::Running || n.state == State::Standby {
            let repeatable = matches!(n.kind, Kind::ManeuverGroup | Kind::Event);
            if repeatable && n.executions < i64::from(n.max_executions) {
                if let Some(t) = n.start_trigger {
                    self.triggers[t].reset(self.state_log.len());
                }
                if let Some(t) = n.stop_trigger {
                    self.triggers[t].reset(self.state_log.len());
                }
                self.set_state(id, Transition::End, State::Standby);
                self.reset_children(id);
            } else {
                self.set_state(id, Transition::End, State::Complete);
            }
            if let Some(slot) = self.nodes[id].action {
                self.actions[slot].running = false;
            }
        }
        if let Some(p) = self.nodes[id].parent {
            self.propagate(p);
        }
    }

    /// Stop element `id` and everything below it.
    pub(crate) fn stop_element(&mut self, id: usize) {
        let children = self.nodes.get(id).map(|n| n.children.clone()).unwrap_or_default();
        for c in children {
            self.stop_element(c);
        }
        let st = self.nodes[id].state;
        if st == State::Complete {
            return;
        }
        if st == State::Standby || st == State::Running {
            self.set_state(id, Transition::Stop, State::Complete);
            if let Some(slot) = self.nodes[id].action {
                self.actions[slot].running = false;
            }
        }
        if let Some(p) = self.nodes[id].parent {
            self.propagate(p);
        }
    }

    /// Children back to init with fresh triggers, so a condition delay counts again from the
    /// next execution (esmini's StoryBoardElement::Reset resets each child's triggers).
    fn reset_children(&mut self, id: usize) {
        let children = self.nodes[id].children.clone();
        for c in children {
            self.reset_children(c);
            self.nodes[c].state = State::Init;
            for t in [self.nodes[c].start_trigger, self.nodes[c].stop_trigger].into_iter().flatten() {
                self.triggers[t].reset(self.state_log.len());
            }
            if let Some(slot) = self.nodes[c].action {
                self.actions[slot].running = false;
            }
        }
    }

    /// A parent whose children are all complete ends (the storyboard excepted).
    fn propagate(&mut self, id: usize) {
        let n = &self.nodes[id];
        if n.kind == Kind::Storyboard || n.state == State::Complete {
            return;
        }
        if n.children.iter().all(|&c| self.nodes[c].state == State::Complete) {
            self.end_element(id);
        }
    }

    /// Evaluate stop and start triggers from `id` down, starting and stopping elements.
    pub(crate) fn eval_triggers(&mut self, id: usize) {
        let Some(n) = self.nodes.get(id) else { return };
        if n.state == State::Running {
            if let Some(t) = n.stop_trigger {
                if self.eval_trigger(t, false) {
                    self.stop_element(id);
                }
            }
        }
        let n = &self.nodes[id];
        if n.state == State::Standby {
            let fire = match n.start_trigger {
                Some(t) => self.eval_trigger(t, true),
                None => true,
            };
            if fire {
                if self.nodes[id].kind == Kind::Event {
                    self.start_event(id);
                } else {
                    self.start_element(id);
                }
            }
        }
        if self.nodes[id].state == State::Running && self.nodes[id].kind != Kind::Event {
            // Index loop: children lists never change after the build, and cloning them every
            // step would allocate.
            for i in 0..self.nodes[id].children.len() {
                let c = self.nodes[id].children[i];
                if self.nodes[c].kind != Kind::Action {
                    self.eval_triggers(c);
                }
            }
        }
    }

    /// Step the running actions below `id`, in document order.
    pub(crate) fn step_tree(&mut self, id: usize) {
        let Some(n) = self.nodes.get(id) else { return };
        if n.state != State::Running {
            return;
        }
        if let Some(slot) = n.action {
            self.step_action(slot);
            return;
        }
        for i in 0..n.children.len() {
            let c = self.nodes[id].children[i];
            self.step_tree(c);
        }
    }
}

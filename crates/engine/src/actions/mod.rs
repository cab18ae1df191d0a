//! Actions at run time: one slot per storyboard action, one instance per actor while it runs.
//! Starting a private action ends the actor's running actions of the same domain
//! (longitudinal / lateral), as esmini does; an action node ends when all its instances are
//! done.

pub mod global;
pub mod lane_change;
pub mod lane_offset;
pub mod speed;
pub mod teleport;

use crate::sim::Sim;
use crate::storyboard::{State, Transition};
use crate::Warning;
use openscenario::{Action, ActionKind, PrivateAction};

pub const LONG: u8 = 1;
pub const LAT: u8 = 2;

/// What an action instance is doing.
#[derive(Debug, Clone)]
pub enum ActionRt {
    Speed(speed::SpeedRt),
    LaneChange(lane_change::LaneChangeRt),
    LaneOffset(lane_offset::LaneOffsetRt),
    /// Nothing left to do.
    Done,
}

#[derive(Debug, Clone)]
pub struct Instance {
    pub entity: Option<usize>,
    pub rt: ActionRt,
}

#[derive(Debug, Clone)]
pub struct ActionSlot<'a> {
    pub node: usize,
    pub model: &'a Action,
    pub actors: Vec<usize>,
    pub instances: Vec<Instance>,
    pub running: bool,
    pub warned: bool,
}

impl<'a> ActionSlot<'a> {
    pub fn new(node: usize, model: &'a Action, actors: Vec<usize>) -> Self {
        ActionSlot { node, model, actors, instances: Vec::new(), running: false, warned: false }
    }

    /// Control domains the action takes over.
    pub fn domains(&self) -> u8 {
        match &self.model.kind {
            ActionKind::Private(p) => match p {
                PrivateAction::Speed { .. }
                | PrivateAction::SpeedProfile { .. }
                | PrivateAction::LongitudinalDistance { .. }
                | PrivateAction::Synchronize { .. } => LONG,
                PrivateAction::LaneChange { .. } | PrivateAction::LaneOffset { .. } | PrivateAction::LateralDistance { .. } => LAT,
                PrivateAction::FollowTrajectory { .. } => LONG | LAT,
                _ => 0,
            },
            _ => 0,
        }
    }
}

impl<'a> Sim<'a> {
    /// Warn once about action slot `slot`.
    pub fn warn_action(&mut self, slot: usize, msg: String) {
        let Some(s) = self.actions.get_mut(slot) else { return };
        if s.warned {
            return;
        }
        s.warned = true;
        let w = Warning::at(&s.model.origin, msg);
        self.warnings.push(w);
    }

    /// End the running actions of the same actors whose domains overlap this one's.
    pub fn end_conflicting_actions(&mut self, slot: usize) {
        let dom = self.actions[slot].domains();
        if dom == 0 {
            return;
        }
        let mut to_end = Vec::new();
        for (i, other) in self.actions.iter().enumerate() {
            if i == slot || !other.running || other.domains() & dom == 0 {
                continue;
            }
            if other.actors.iter().any(|a| self.actions[slot].actors.contains(a)) {
                to_end.push(other.node);
            }
        }
        for n in to_end {
            self.end_element(n);
        }
    }

    /// Start action slot `slot`: running state, one instance per actor.
    pub fn start_action(&mut self, slot: usize) {
        let node = self.actions[slot].node;
        self.set_state(node, Transition::Start, State::Running);
        self.actions[slot].running = true;
        self.actions[slot].instances.clear();
        let model = self.actions[slot].model;
        match &model.kind {
            ActionKind::Private(p) => {
                for k in 0..self.actions[slot].actors.len() {
                    let e = self.actions[slot].actors[k];
                    let rt = self.start_private(slot, e, p);
                    self.actions[slot].instances.push(Instance { entity: Some(e), rt });
                }
            }
            ActionKind::Global(g) => {
                self.run_global(slot, g);
                self.actions[slot].instances.push(Instance { entity: None, rt: ActionRt::Done });
            }
            ActionKind::CustomCommand { command_type } => {
                self.warn_action(slot, format!("custom command `{command_type}` is not interpreted"));
            }
            ActionKind::Unsupported { element } => {
                self.warn_action(slot, format!("{element} is not supported; the action completes at once"));
            }
        }
    }

    fn start_private(&mut self, slot: usize, e: usize, p: &'a PrivateAction) -> ActionRt {
        match p {
            PrivateAction::Speed { dynamics, target } => self.start_speed(slot, e, dynamics, target),
            PrivateAction::LaneChange { dynamics, target, target_lane_offset } => {
                self.start_lane_change(slot, e, dynamics, target, target_lane_offset.unwrap_or(0.0))
            }
            PrivateAction::LaneOffset { shape, max_lateral_acc, target, .. } => self.start_lane_offset(slot, e, *shape, *max_lateral_acc, target),
            PrivateAction::Teleport(pos) => {
                self.teleport(slot, e, pos);
                ActionRt::Done
            }
            PrivateAction::Visibility { graphics, .. } => {
                if let Some(en) = self.entities.get_mut(e) {
                    en.visible = *graphics;
                }
                ActionRt::Done
            }
            PrivateAction::ActivateController { lateral, longitudinal, .. } => {
                let on = lateral.unwrap_or(true) || longitudinal.unwrap_or(true);
                if let Some(en) = self.entities.get_mut(e) {
                    en.controller_active = on;
                }
                ActionRt::Done
            }
            PrivateAction::AssignController { controller, .. } => {
                if let Some(c) = controller {
                    self.warn_action(slot, format!("controller `{}` is recorded but not modelled; the default controller drives", c.name));
                }
                ActionRt::Done
            }
            other => {
                self.warn_action(slot, format!("{} is not supported yet; the action completes at once", other.element_name()));
                ActionRt::Done
            }
        }
    }

    /// Step action slot `slot`; end its node when every instance is done.
    pub fn step_action(&mut self, slot: usize) {
        if !self.actions[slot].running {
            return;
        }
        let mut all_done = true;
        for k in 0..self.actions[slot].instances.len() {
            let inst = &mut self.actions[slot].instances[k];
            let Some(e) = inst.entity else { continue };
            // Take the state out so the entity can be borrowed mutably alongside it.
            let mut rt = std::mem::replace(&mut inst.rt, ActionRt::Done);
            let done = match &mut rt {
                ActionRt::Speed(s) => self.step_speed(e, s),
                ActionRt::LaneChange(l) => self.step_lane_change(e, l),
                ActionRt::LaneOffset(l) => self.step_lane_offset(e, l),
                ActionRt::Done => true,
            };
            if !done {
                all_done = false;
                self.actions[slot].instances[k].rt = rt;
            }
        }
        if all_done && self.actions[slot].running {
            let node = self.actions[slot].node;
            self.end_element(node);
        }
    }
}

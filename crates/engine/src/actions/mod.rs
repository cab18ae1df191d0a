//! Actions at run time: one slot per storyboard action, one instance per actor while it runs.
//! Starting a private action ends the actor's running actions of the same domain
//! (longitudinal / lateral), as esmini does; an action node ends when all its instances are
//! done.

pub(crate) mod add_delete_entity;
pub(crate) mod dynamic_constraints;
pub(crate) mod follow_trajectory;
pub(crate) mod global;
pub(crate) mod lane_change;
pub(crate) mod lane_offset;
pub(crate) mod lat_distance;
pub(crate) mod long_distance;
pub(crate) mod override_controller;
pub(crate) mod routing;
pub(crate) mod speed;
pub(crate) mod speed_profile;
pub(crate) mod state;
pub(crate) mod synchronize;
pub(crate) mod teleport;
pub(crate) mod traffic_signal;
pub(crate) mod trailer;

use self::state::{ActionRt, Instance};
use crate::external::overridden::{overridden, Overridden};
use crate::sim::Sim;
use crate::storyboard::{State, Transition};
use crate::Diagnostic;
use openscenario::{Action, ActionKind, GlobalAction, PrivateAction};

impl<'a> Sim<'a> {
    /// Warn once about action slot `slot`.
    pub(crate) fn warn_action(&mut self, slot: usize, msg: String) {
        let Some(s) = self.actions.get_mut(slot) else { return };
        if s.warned {
            return;
        }
        s.warned = true;
        let w = Diagnostic::at(&s.model.origin, msg);
        self.warnings.push(w);
    }

    /// End the running actions of the same actors whose domains overlap this one's.
    pub(crate) fn end_conflicting_actions(&mut self, slot: usize) {
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

    /// The fate of private action `p` of slot `slot` on entity `e` (external/overridden.rs;
    /// `Runs` unless `e` is driven from outside), warned once per slot when `tell`.
    fn overridden_on(&mut self, slot: usize, e: usize, p: &PrivateAction, tell: bool) -> Overridden {
        if !self.outside(e) {
            // a controller in override mode on the lateral domain holds the lateral actions
            // (controllers::lateral_overridden), a trajectory too: FollowTrajectoryAction::Start
            // and ::Step return at once then, so it neither moves the entity nor ends
            // (a LateralDistanceAction is held by the longitudinal one instead: `idles_under_override`)
            let lateral = matches!(p, PrivateAction::LaneChange { .. } | PrivateAction::LaneOffset { .. } | PrivateAction::FollowTrajectory { .. });
            return if lateral && self.lateral_overridden(e) { Overridden::Idles } else { Overridden::Runs };
        }
        let fate = overridden(p);
        if let Some(note) = crate::external::overridden::note(fate, p.element_name(), self.entities.get(e).map_or("", |en| en.name.as_str())).filter(|_| tell) {
            self.warn_action(slot, note);
        }
        fate
    }

    /// Whether the running action `rt` on entity `e` waits this step because a controller in
    /// override mode holds the entity's longitudinal domain: esmini's LongDistanceAction::Step,
    /// SynchronizeAction::Step and LatDistanceAction::Step return at once then (the action
    /// neither moves the entity nor ends by itself). LatDistanceAction tests
    /// `ControlDomains::DOMAIN_LAT`, an index whose value 1 is the longitudinal *mask*, so a
    /// lateral distance waits under an ACC in override mode and not under a lateral-only one.
    fn idles_under_override(&self, e: usize, rt: &ActionRt) -> bool {
        matches!(rt, ActionRt::LongDistance(_) | ActionRt::Synchronize(_) | ActionRt::LatDistance(_)) && self.long_domain_overridden(e)
    }

    /// Start action slot `slot`: running state, one instance per actor.
    pub(crate) fn start_action(&mut self, slot: usize) {
        if self.entity_action_refused(slot) {
            return;
        }
        let node = self.actions[slot].node;
        self.set_state(node, Transition::Start, State::Running);
        self.actions[slot].running = true;
        // An instance still holding its state (stopped, or overridden, before it finished)
        // leaves it to the next execution as a finished one does.
        let previous = std::mem::take(&mut self.actions[slot].instances);
        for i in &previous {
            if let Some(e) = i.entity {
                self.actions[slot].keep(e, &i.rt);
            }
        }
        let model = self.actions[slot].model;
        match &model.kind {
            ActionKind::Private(p) => {
                for k in 0..self.actions[slot].actors.len() {
                    let e = self.actions[slot].actors[k];
                    // A deleted entity is still acted on (esmini keeps it in its pool and
                    // its actions step): it shows again as they left it. An action of a ghost's
                    // restarting event starts on the rewound clock (ghost_time_shift).
                    let (saved, shift) = (self.time, self.ghost_time_shift(slot, e, true));
                    self.time = saved - shift;
                    let rt = self.start_private(slot, e, p);
                    self.time = saved;
                    self.actions[slot].instances.push(Instance { entity: Some(e), rt });
                }
                let instances = &self.actions[slot].instances;
                if !instances.is_empty() && instances.iter().all(|i| matches!(i.rt, ActionRt::EndedAtStart)) {
                    self.end_element(node);
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
        match self.overridden_on(slot, e, p, true) {
            Overridden::Idles => return ActionRt::Overridden,
            Overridden::Ignored => return ActionRt::Done,
            Overridden::Ends | Overridden::Runs => {}
        }
        match p {
            PrivateAction::Speed { dynamics, target } => self.start_speed(slot, e, dynamics, target),
            PrivateAction::LongitudinalDistance { entity, distance, time_gap, freespace, continuous, coordinate_system, displacement, constraints } => {
                let spec = long_distance::LongDistanceSpec {
                    entity,
                    distance: *distance,
                    time_gap: *time_gap,
                    freespace: *freespace,
                    continuous: *continuous,
                    coordinate_system: *coordinate_system,
                    displacement: *displacement,
                    constraints: constraints.as_ref(),
                };
                self.start_long_distance(slot, e, &spec)
            }
            PrivateAction::LateralDistance { entity, distance, freespace, continuous, coordinate_system, displacement, constraints } => {
                let spec = lat_distance::LatDistanceSpec {
                    entity,
                    distance: *distance,
                    freespace: *freespace,
                    continuous: *continuous,
                    coordinate_system: *coordinate_system,
                    displacement: *displacement,
                    constraints: constraints.as_ref(),
                };
                self.start_lat_distance(slot, e, &spec)
            }
            PrivateAction::Synchronize { master, target_position_master, target_position, final_speed, target_tolerance_master, target_tolerance } => {
                let spec = synchronize::SynchronizeSpec {
                    master,
                    target_master: target_position_master,
                    target: target_position,
                    final_speed: final_speed.as_ref(),
                    tolerances: (*target_tolerance_master, *target_tolerance),
                };
                self.start_synchronize(slot, e, &spec)
            }
            PrivateAction::LaneChange { dynamics, target, target_lane_offset } => {
                self.start_lane_change(slot, e, dynamics, target, target_lane_offset.unwrap_or(0.0))
            }
            PrivateAction::LaneOffset { shape, max_lateral_acc, target, .. } => self.start_lane_offset(slot, e, *shape, *max_lateral_acc, target),
            PrivateAction::AssignRoute(route) => self.assign_route(slot, e, route),
            PrivateAction::AcquirePosition(pos) => self.acquire_position(slot, e, pos),
            PrivateAction::SpeedProfile { entity, following_mode, constraints, entries } => {
                self.start_speed_profile(slot, e, entity.as_deref(), *following_mode, constraints.as_ref(), entries)
            }
            PrivateAction::FollowTrajectory { trajectory, time_reference, following_mode, initial_distance_offset } => {
                self.start_follow_trajectory(slot, e, trajectory, time_reference, *following_mode, *initial_distance_offset)
            }
            PrivateAction::Teleport(pos) => {
                // esmini aligns the trailers behind a teleported tow vehicle, not when the
                // teleport was ignored (TeleportAction::Start)
                if self.teleport(slot, e, pos) {
                    self.align_chain(e);
                }
                ActionRt::Done
            }
            PrivateAction::Visibility { graphics, .. } => {
                if let Some(en) = self.entities.get_mut(e) {
                    en.visible = *graphics;
                }
                ActionRt::Done
            }
            PrivateAction::ActivateController { lateral, longitudinal, controller_ref, object_controller_ref, .. } => {
                // esmini's ScenarioReader::parseActivateControllerAction reads the name from
                // `controllerRef`, and from a 1.3 file from `objectControllerRef` instead.
                // (an empty name names none: esmini then takes the most recently assigned)
                let name = if self.scenario.header.rev_minor >= 3 { object_controller_ref } else { controller_ref };
                let name = name.as_ref().filter(|n| !n.is_empty());
                let on = lateral.unwrap_or(true) || longitudinal.unwrap_or(true);
                self.activate_outside_driver(slot, e, lateral.unwrap_or(true), longitudinal.unwrap_or(true));
                if let Some(en) = self.entities.get_mut(e) {
                    en.controller_active = on;
                }
                // a name that names none of the entity's controllers activates nothing
                let found = self.controllers.iter().any(|c| c.entity == e && name.is_none_or(|n| &c.name == n));
                if found {
                    self.switch_off_conflicting(e, *lateral, *longitudinal);
                }
                self.activate_controller(e, name.map(String::as_str), lateral.unwrap_or(true), longitudinal.unwrap_or(true));
                // ActivateControllerAction::Start ends the action only when it found a
                // controller to activate; without one (none assigned, or none of that name) it
                // neither starts nor ends it, and its event runs on until the stop.
                if found {
                    // it calls End() from Start: complete before later triggers are evaluated
                    ActionRt::EndedAtStart
                } else {
                    ActionRt::Lingers
                }
            }
            PrivateAction::AssignController { controller, object_controller_name, activate_longitudinal, activate_lateral, .. } => {
                if let Some(c) = controller {
                    // esmini's ScenarioReader names an assigned controller after its
                    // ObjectController wrapper, which only a 1.3 file has, and gives it the
                    // empty name otherwise: an activation by the Controller's own name finds none.
                    let name = if self.scenario.header.rev_minor >= 3 { object_controller_name.clone().unwrap_or_default() } else { String::new() };
                    self.assign_controller(e, c, &name, Some(slot));
                    let (lat, long) = (*activate_lateral == Some(true), *activate_longitudinal == Some(true));
                    if lat || long {
                        self.activate_outside_driver(slot, e, lat, long);
                    }
                    if lat || long {
                        self.activate_controller(e, None, lat, long);
                    }
                }
                // AssignControllerAction::Start never ends it, and its Step is empty.
                ActionRt::Lingers
            }
            PrivateAction::LightState { light_type, state, transition_time } => {
                let (time, entity) = (self.time, self.entities.get(e).map_or(String::new(), |en| en.name.clone()));
                self.lights.push(crate::recorded::LightChange {
                    time,
                    entity,
                    light: light_type.clone(),
                    state: state.clone(),
                    transition_time: *transition_time,
                });
                self.warn_action(
                    slot,
                    "LightStateAction: the light state is kept in the run's light log (Run::lights); CommonRoad 2020a has no place for vehicle lights".into(),
                );
                ActionRt::Done
            }
            PrivateAction::OverrideControllerValue(values) => self.start_override(slot, e, values),
            PrivateAction::ConnectTrailer { trailer } => {
                self.connect_trailer(slot, e, trailer);
                ActionRt::Done
            }
            PrivateAction::DisconnectTrailer => {
                self.disconnect_trailer(e);
                ActionRt::Done
            }
            other => {
                self.warn_action(slot, format!("{} is not supported yet; the action completes at once", other.element_name()));
                ActionRt::Done
            }
        }
    }

    /// Step action slot `slot`; end its node when every instance is done.
    pub(crate) fn step_action(&mut self, slot: usize) {
        if !self.actions[slot].running {
            return;
        }
        let mut all_done = true;
        // While the ghost runs ahead only its actions step (ghost/, `steps_during_restart`).
        let held = self.ghost_restarting();
        for k in 0..self.actions[slot].instances.len() {
            let Some(e) = self.actions[slot].instances[k].entity else { continue };
            if held && !self.steps_during_restart(e) {
                all_done = false;
                continue;
            }
            // An entity that became external while its action ran (external/overridden.rs). An
            // instance already done did what it did before, and a speed change whose
            // transition is over loses nothing by ending: only the others are told.
            let rt = &self.actions[slot].instances[k].rt;
            if let (true, ActionKind::Private(p)) = (self.outside(e) || self.lateral_overridden(e), &self.actions[slot].model.kind) {
                if !matches!(rt, ActionRt::Done | ActionRt::EndedAtStart) {
                    let cut_short = !matches!(rt, ActionRt::Speed(s) if s.transition.param >= s.transition.param_target);
                    if self.overridden_on(slot, e, p, cut_short) == Overridden::Idles {
                        all_done = false;
                        continue;
                    }
                }
            }
            if self.idles_under_override(e, &self.actions[slot].instances[k].rt) {
                all_done = false;
                continue;
            }
            let inst = &mut self.actions[slot].instances[k];
            // Take the state out so the entity can be borrowed mutably alongside it.
            let mut rt = std::mem::replace(&mut inst.rt, ActionRt::Done);
            // The longitudinal actions, and LatDistanceAction::Step (it re-sets the speed it has),
            // set the speed in every step they run (esmini's Object::SetSpeed, its SPEED dirty
            // bit): `after_move` derives none from the motion. Lane changes and lane offsets do not.
            let sets_speed = matches!(
                rt,
                ActionRt::Speed(_)
                    | ActionRt::SpeedProfile(_)
                    | ActionRt::Synchronize(_)
                    | ActionRt::LongDistance(_)
                    | ActionRt::FollowTrajectory(_)
                    | ActionRt::LatDistance(_)
            );
            if let (true, Some(en)) = (sets_speed, self.entities.get_mut(e)) {
                en.speed_set = true;
            }
            let (saved, shift) = (self.time, self.ghost_time_shift(slot, e, false));
            self.time = saved - shift;
            let done = match &mut rt {
                ActionRt::Speed(s) => self.step_speed(e, s),
                ActionRt::LaneChange(l) => self.step_lane_change(e, l),
                ActionRt::LaneOffset(l) => self.step_lane_offset(e, l),
                ActionRt::FollowTrajectory(f) => self.step_follow_trajectory(e, f),
                ActionRt::SpeedProfile(p) => self.step_speed_profile(e, p),
                ActionRt::Synchronize(y) => self.step_synchronize(e, y),
                ActionRt::LongDistance(d) => self.step_long_distance(e, d),
                ActionRt::LatDistance(d) => self.step_lat_distance(e, d),
                ActionRt::Overridden | ActionRt::Lingers => false,
                ActionRt::Done | ActionRt::EndedAtStart => true,
            };
            self.time = saved;
            if done {
                self.actions[slot].keep(e, &rt);
            } else {
                all_done = false;
                self.actions[slot].instances[k].rt = rt;
            }
        }
        if all_done && self.actions[slot].running {
            let node = self.actions[slot].node;
            if finishes_by_stop(self.actions[slot].model) {
                self.stop_element(node);
            } else {
                self.end_element(node);
            }
        }
    }
}

/// The global actions esmini finishes with OSCAction::Stop in their Step (OSCGlobalAction.cpp):
/// they go running → stopTransition → complete, so a StoryboardElementStateCondition on their
/// endTransition never holds (one on their event's end still does).
fn finishes_by_stop(model: &Action) -> bool {
    matches!(
        &model.kind,
        ActionKind::Global(
            GlobalAction::Environment(_)
                | GlobalAction::ParameterSet { .. }
                | GlobalAction::VariableSet { .. }
                | GlobalAction::VariableModify { .. }
                | GlobalAction::TrafficSignalState { .. }
                | GlobalAction::AddEntity { .. }
                | GlobalAction::DeleteEntity { .. }
        )
    )
}

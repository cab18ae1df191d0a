//! Controllers: the driver models a scenario assigns to entities (ObjectController or
//! AssignControllerAction) and switches on with ActivateControllerAction. A controller's type is
//! its `esminiController` property, else its name (esmini's rule).
//!
//! Modelled: ACCController (see `acc`), ALKSController (the same model, see `alks`), the
//! others listed in `assign_controller` (LoomingController without its steering). Every
//! other type leaves the entity to the default controller and the storyboard, with a warning
//! naming it; the ones that need a human or an outside process (Interactive, External, SUMO,
//! HID, UDP driver) say so.

pub(crate) mod acc;
pub(crate) mod alks;
pub(crate) mod alks_r157;
pub(crate) mod analog_vehicle;
pub(crate) mod follow_ghost;
pub(crate) mod follow_reference;
pub(crate) mod follow_route;
pub(crate) mod followers;
pub(crate) mod forward_delta;
pub(crate) mod kinematic_vehicle;
pub(crate) mod lane_lock;
pub(crate) mod lane_router;
pub(crate) mod looming;
pub(crate) mod natural_driver;
pub(crate) mod offroad_follower;
pub(crate) mod state;
pub(crate) mod step_order;

use self::state::{ControllerRt, ControllerSlot};
use crate::sim::Sim;
use crate::Diagnostic;
use openscenario::Controller;

/// Types that need a driver or a co-simulator outside osc2cr.
const OUTSIDE_INPUT: [&str; 6] =
    ["InteractiveController", "ExternalController", "SumoController", "HIDController", "UDPDriverController", "ExternalDriverModel"];

/// The esmini type of a controller.
pub(crate) fn controller_type(c: &Controller) -> &str {
    c.properties.get("esminiController").unwrap_or(c.name.as_str())
}

impl<'a> Sim<'a> {
    /// Runs `step` on each controller in esmini's order (`step_order`), its entity being in the
    /// run: the controller is taken out of its slot meanwhile (so that `step` may use the whole
    /// simulation) and put back after. Each kind's stepping picks its own variant; `wants` says
    /// beforehand which controllers `step` acts on (its variant, active), so that the others are
    /// not moved out and back for nothing (a controller's state is large; `step` leaves them as
    /// they are).
    pub(crate) fn for_each_controller(&mut self, wants: impl Fn(&ControllerRt) -> bool, mut step: impl FnMut(&mut Self, usize, &mut ControllerRt)) {
        if !self.any_controller {
            return;
        }
        for k in 0..self.controllers.len() {
            let Some(slot) = self.controllers.get(k) else { continue };
            let e = slot.entity;
            if !slot.rt.as_ref().is_some_and(&wants) {
                continue;
            }
            // esmini's ScenarioEngine::step steps every active controller whether or not its
            // entity is in the simulation (AddEntityAction and DeleteEntityAction leave the
            // controllers alone): a deleted entity's speed goes on changing (fixture
            // acc_steps_while_away.xosc) and a ghost follower's vehicle drives on, placing the
            // entity where it drove once it is back (follow_ghost_steps_while_away.xosc).
            let Some(mut c) = self.controllers.get_mut(k).and_then(|s| s.rt.take()) else { continue };
            step(self, e, &mut c);
            if let Some(slot) = self.controllers.get_mut(k) {
                slot.rt = Some(c);
            }
        }
    }

    /// The modelled controllers assigned to entity `e`, in esmini's order.
    pub(crate) fn controllers_of(&self, e: usize) -> impl Iterator<Item = &ControllerRt> {
        self.controllers.iter().filter(move |c| c.entity == e).filter_map(|c| c.rt.as_ref())
    }

    /// The first modelled controller of entity `e` that `pick` takes.
    pub(crate) fn controller_of_mut<T>(&mut self, e: usize, pick: impl FnMut(&mut ControllerRt) -> Option<&mut T>) -> Option<&mut T> {
        self.controllers.iter_mut().filter(|c| c.entity == e).filter_map(|c| c.rt.as_mut()).find_map(pick)
    }

    /// Assign controller `c`, known as `name` to activations, to entity `e` (by the
    /// AssignControllerAction in action slot `assigned_by`, else as its ObjectController);
    /// warns when its type is not modelled. esmini
    /// keeps the entity's other controllers, active or not (Object::AssignController appends);
    /// an AssignControllerAction that runs again assigns its own controller again, which keeps
    /// its state and becomes the entity's most recent one.
    pub(crate) fn assign_controller(&mut self, e: usize, c: &Controller, name: &str, assigned_by: Option<usize>) {
        self.assignments += 1;
        let assigned = self.assignments;
        if let Some(again) = self.controllers.iter_mut().find(|x| x.entity == e && assigned_by.is_some() && x.assigned_by == assigned_by) {
            again.assigned = assigned;
            return;
        }
        if self.named_external(e) {
            let name = self.entities.get(e).map_or("", |en| en.name.as_str());
            self.warnings.push(Diagnostic::at(&c.origin, format!("controller `{}` of `{name}` is not stepped: the entity is driven from outside", c.name)));
            return;
        }
        let kind = controller_type(c);
        let rt = match kind {
            "ACCController" => Some(ControllerRt::Acc(acc::state::AccRt::new(c))),
            "ALKSController" => Some(ControllerRt::Acc(alks::new(c))),
            "ALKS_R157SM_Controller" => {
                let (rt, note) = alks_r157::state::AlksR157Rt::new(c);
                if let Some(n) = note {
                    self.warnings.push(Diagnostic::at(&c.origin, n));
                }
                Some(ControllerRt::AlksR157(Box::new(rt)))
            }
            "NaturalDriver" => Some(ControllerRt::NaturalDriver(Box::new(natural_driver::state::NaturalDriverRt::new(c)))),
            "FollowGhostController" => Some(ControllerRt::FollowGhost(Box::new(follow_ghost::state::FollowGhostRt::new(c)))),
            "FollowReferenceController" => Some(ControllerRt::FollowReference(Box::new(follow_reference::state::FollowReferenceRt::new(c)))),
            "FollowRouteController" => Some(ControllerRt::FollowRoute(Box::new(follow_route::state::FollowRouteRt::new(c)))),
            "OffroadFollower" => Some(ControllerRt::OffroadFollower(Box::new(offroad_follower::state::OffroadFollowerRt::new(c)))),
            "LoomingController" => {
                if self.net.is_some_and(|n| n.roads.iter().any(|r| r.superelevation.iter().any(|c| c.b != 0.0 || c.c != 0.0 || c.d != 0.0))) {
                    self.warnings.push(Diagnostic::at(&c.origin, looming::APPROXIMATION.to_string()));
                }
                Some(ControllerRt::Looming(looming::state::LoomingRt::new(c)))
            }
            _ => None,
        };
        if rt.is_none() && self.waits_for_outside_driver(kind) {
            self.await_outside_driver(e, c);
        } else if rt.is_none() {
            let why = if OUTSIDE_INPUT.contains(&kind) { "needs a driver or a process outside osc2cr" } else { "is not modelled" };
            self.warnings.push(Diagnostic::at(
                &c.origin,
                format!("controller `{}` ({kind}) {why}; the default controller drives and the storyboard's actions apply", c.name),
            ));
        }
        self.any_controller |= rt.is_some();
        let rank = self.controller_rank(assigned_by);
        let at = self.controllers.iter().position(|x| x.rank > rank).unwrap_or(self.controllers.len());
        self.controllers.insert(at, ControllerSlot { entity: e, rank, assigned_by, assigned, name: name.to_string(), rt });
    }

    /// The controller an ActivateControllerAction activates: the entity's first one of that
    /// name in its list (Object::GetController; none when no such name: esmini logs an error
    /// and activates nothing), or, naming none, entity `e`'s most recently assigned (esmini's
    /// `controllers_.back()`); `None` also when that is not modelled.
    fn to_activate_mut(&mut self, e: usize, name: Option<&str>) -> Option<&mut ControllerRt> {
        let mine = self.controllers.iter_mut().filter(|c| c.entity == e);
        match name {
            Some(name) => mine.filter(|c| c.name == name).min_by_key(|c| c.assigned),
            None => mine.max_by_key(|c| c.assigned),
        }
        .and_then(|c| c.rt.as_mut())
    }

    /// Before OpenSCENARIO 1.3 only one controller is active at a time: esmini's
    /// ActivateControllerAction::Start first switches off, whole, the first controller of the
    /// entity's list (assignment order) active on a domain the action turns on ("true"; the
    /// longitudinal domain asked first), one at most (`Object::GetControllerActiveOnDomainMask`,
    /// `Controller::Deactivate`). From 1.3 on it switches no other controller off.
    pub(crate) fn switch_off_conflicting(&mut self, e: usize, lateral: Option<bool>, longitudinal: Option<bool>) {
        if self.scenario.header.rev_minor >= 3 {
            return;
        }
        for domain_lateral in [false, true] {
            let asked = if domain_lateral { lateral } else { longitudinal };
            if asked != Some(true) {
                continue;
            }
            let first = (0..self.controllers.len())
                .filter(|&k| self.controllers.get(k).is_some_and(|c| c.entity == e && c.rt.as_ref().is_some_and(|rt| rt.active_on(domain_lateral))))
                .min_by_key(|&k| self.controllers.get(k).map_or(0, |c| c.assigned));
            let Some(k) = first else { continue };
            let Some(mut rt) = self.controllers.get_mut(k).and_then(|c| c.rt.take()) else { return };
            match &mut rt {
                ControllerRt::Acc(a) => a.active = false,
                ControllerRt::AlksR157(a) => a.active = false,
                ControllerRt::NaturalDriver(n) => n.active = false,
                ControllerRt::FollowGhost(f) => f.active = false,
                ControllerRt::FollowReference(f) => f.active = false,
                ControllerRt::FollowRoute(f) => self.deactivate_follow_route(e, f),
                ControllerRt::Looming(l) => l.active = false,
                ControllerRt::OffroadFollower(f) => f.active = false,
            }
            if let Some(c) = self.controllers.get_mut(k) {
                c.rt = Some(rt);
            }
            return;
        }
    }

    /// ActivateControllerAction (or an AssignControllerAction that activates) on entity `e` for
    /// the given domains: its most recently assigned controller (the one the AssignControllerAction
    /// just assigned). esmini activates a controller on the requested domains it operates on
    /// (Controller::Activate): ACC, ALKS, NaturalDriver and Looming on the longitudinal one only;
    /// the entity's other active controllers stay on (OpenSCENARIO 1.3: ActivateControllerAction::
    /// Start switches the domains off on the controller it then activates; an
    /// AssignControllerAction switches none off).
    pub(crate) fn activate_controller(&mut self, e: usize, name: Option<&str>, lateral: bool, longitudinal: bool) {
        let Some(speed) = self.entities.get(e).map(|en| en.speed) else { return };
        let (net, scenario) = (self.net, self.scenario);
        let Some(en) = self.entities.get(e).cloned() else { return };
        let mut align = false;
        match self.to_activate_mut(e, name) {
            Some(ControllerRt::Acc(a)) => a.activate(speed, longitudinal),
            Some(ControllerRt::AlksR157(a)) => a.activate(speed, lateral, longitudinal),
            Some(ControllerRt::NaturalDriver(a)) => a.activate(speed, longitudinal),
            Some(ControllerRt::FollowGhost(f)) => f.activate(&en, longitudinal),
            Some(ControllerRt::FollowReference(f)) => f.activate(&en, follow_reference::wheelbase(scenario, e)),
            Some(ControllerRt::FollowRoute(f)) => f.activate(longitudinal),
            Some(ControllerRt::Looming(l)) => {
                l.activate(&en, longitudinal, crate::entities::position_heading(net, &en));
                align = lateral;
            }
            Some(ControllerRt::OffroadFollower(f)) => f.activate(&en, lateral, longitudinal),
            None => {}
        }
        if align {
            self.align_to_road_heading(e);
        }
    }

    /// The first of entity `e`'s modelled controllers, in its assignment order, that `active`
    /// takes (esmini's `Object::controllers_`: Object::AssignController appends, and one assigned
    /// again moves to the end).
    fn first_active(&self, e: usize, active: impl Fn(&ControllerRt) -> bool) -> Option<&ControllerRt> {
        self.controllers
            .iter()
            .filter(|c| c.entity == e)
            .filter_map(|c| c.rt.as_ref().filter(|rt| active(rt)).map(|rt| (c.assigned, rt)))
            .min_by_key(|(assigned, _)| *assigned)
            .map(|(_, rt)| rt)
    }

    /// Whether controller `c` is active on the longitudinal domain.
    fn active_on_long(c: &ControllerRt) -> bool {
        match c {
            ControllerRt::Acc(a) => a.active,
            ControllerRt::AlksR157(a) => a.active && a.longitudinal,
            ControllerRt::Looming(l) => l.active,
            ControllerRt::NaturalDriver(n) => n.active,
            ControllerRt::FollowGhost(f) => f.active && f.longitudinal,
            ControllerRt::FollowReference(f) => f.active,
            ControllerRt::FollowRoute(f) => f.active_longitudinal(),
            ControllerRt::OffroadFollower(f) => f.holds_longitudinal(),
        }
    }

    /// Whether controller `c` is active on the lateral domain (the types that hold it).
    fn active_on_lat(c: &ControllerRt) -> bool {
        match c {
            ControllerRt::AlksR157(a) => a.active && a.lateral,
            ControllerRt::OffroadFollower(f) => f.holds_lateral(),
            ControllerRt::FollowReference(f) => f.active,
            ControllerRt::FollowGhost(f) => f.active,
            _ => false,
        }
    }

    /// Whether a controller of entity `e` in override mode owns its longitudinal motion now
    /// (esmini's `Object::IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LONG)`): an
    /// active ACC/ALKS, Looming or ALKS R157 in override mode, a FollowReference (always in
    /// override mode, with or without a ghost: the ghost takes the storyboard's actions, the
    /// entity keeps its Init ones), a FollowRoute controller during its lane change.
    /// esmini asks only the first controller of the entity's list (assignment order) that is
    /// active on the domain: an additive ACC assigned before an ALKS R157 in override mode
    /// leaves the domain to the actions.
    pub(crate) fn longitudinal_overridden(&self, e: usize) -> bool {
        if self.outside(e) {
            return true;
        }
        self.first_active(e, Self::active_on_long).is_some_and(|c| match c {
            ControllerRt::Acc(a) => a.overrides_longitudinal(),
            ControllerRt::FollowRoute(f) => f.overrides_longitudinal(),
            ControllerRt::OffroadFollower(f) => f.holds_longitudinal(),
            // ControllerLooming operates on the longitudinal domain, in override mode unless
            // its `mode` says additive.
            ControllerRt::Looming(l) => l.active && l.override_mode,
            // ControllerALKS_R157SM operates on both domains (the Controller default).
            ControllerRt::AlksR157(a) => a.active && a.override_mode && a.longitudinal,
            // ControllerFollowReference forces override mode on both domains.
            ControllerRt::FollowReference(f) => f.active,
            _ => false,
        })
    }

    /// Whether the first controller of entity `e` active on its longitudinal domain holds it
    /// in override mode: esmini's `Object::IsControllerModeOnDomains(MODE_OVERRIDE,
    /// DOMAIN_MASK_LONG)` over every controller type: `longitudinal_overridden`'s set (the one
    /// a SpeedAction is ended under so far: ACC/ALKS, Looming, ALKS R157, OffroadFollower,
    /// FollowReference, FollowRoute during its lane change, an entity driven from outside) and
    /// besides a NaturalDriver unless additive.
    pub(crate) fn long_domain_overridden(&self, e: usize) -> bool {
        if self.longitudinal_overridden(e) {
            return true;
        }
        // (ControllerFollowGhost is in override mode on the domains it is active on.)
        self.first_active(e, Self::active_on_long).is_some_and(|c| {
            matches!(c, ControllerRt::NaturalDriver(n) if n.active && n.override_mode)
                || matches!(c, ControllerRt::FollowGhost(f) if f.active && f.longitudinal)
        })
    }

    /// Whether an active controller of entity `e` in override mode owns its lateral or
    /// longitudinal motion: esmini's `Object::IsControllerModeOnAnyOfDomains(MODE_OVERRIDE,
    /// DOMAIN_MASK_LAT_AND_LONG)`, under which TeleportAction::Start does nothing. Each type's
    /// mode as esmini gives it: ACC/ALKS additive unless `mode` says override (ControllerACC);
    /// Looming, NaturalDriver and ALKS R157 override unless it says additive (the Controller
    /// base); FollowGhost and FollowReference always override; FollowRoute only while it
    /// changes lanes; an OffroadFollower on whichever domain it is active (ControllerOffroadFollower
    /// keeps the Controller base's mode, override unless a `mode` property says additive; the
    /// engine reads no `mode` for it). Only the first controller active on either domain
    /// (assignment order) is asked.
    pub(crate) fn overrides_motion(&self, e: usize) -> bool {
        self.first_active(e, |c| Self::active_on_long(c) || Self::active_on_lat(c)).is_some_and(|c| match c {
            ControllerRt::Acc(a) => a.overrides_longitudinal(),
            ControllerRt::Looming(l) => l.active && l.override_mode,
            ControllerRt::NaturalDriver(n) => n.active && n.override_mode,
            ControllerRt::AlksR157(a) => a.active && a.override_mode,
            ControllerRt::FollowGhost(f) => f.active,
            ControllerRt::FollowReference(f) => f.active,
            ControllerRt::FollowRoute(f) => f.overrides_longitudinal(),
            ControllerRt::OffroadFollower(f) => f.active,
        })
    }

    /// Whether the first controller of entity `e` active on its lateral domain holds it in
    /// override mode (esmini's `IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LAT)`),
    /// under which a lane change, a lane offset or a trajectory does nothing and never ends
    /// (LatLaneChangeAction, LatLaneOffsetAction, FollowTrajectoryAction: Start and Step return
    /// early; a lateral distance action waits on the longitudinal domain instead,
    /// `long_domain_overridden`): an ALKS R157 controller activated laterally in override mode, an
    /// OffroadFollower, an active FollowGhost or FollowReference. (ACC, ALKS, Looming and
    /// NaturalDriver operate on the longitudinal domain only.)
    pub(crate) fn lateral_overridden(&self, e: usize) -> bool {
        self.first_active(e, Self::active_on_lat).is_some_and(|c| match c {
            ControllerRt::AlksR157(a) => a.active && a.override_mode && a.lateral,
            ControllerRt::OffroadFollower(f) => f.holds_lateral(),
            // FollowGhost and FollowReference force override mode on both domains; with a
            // ghost the storyboard's actions drive the ghost, but the entity keeps its Init
            // actions (ScenarioEngine::SetupGhost copies them), which idle from activation.
            ControllerRt::FollowReference(f) => f.active,
            ControllerRt::FollowGhost(f) => f.active,
            _ => false,
        })
    }

    /// While the ghost's run is rewound (RESTARTING) controllers do not step, but injected
    /// actions do: a NaturalDriver's pending lane change starts, a running one steps once the
    /// time before the step (`t`) is no longer below 0 (LatLaneChangeAction::Step).
    pub(crate) fn step_injected_during_restart(&mut self, t: f64, dt: f64) {
        if !self.any_controller {
            return;
        }
        for k in 0..self.controllers.len() {
            let Some(e) = self.controllers.get(k).map(|c| c.entity) else { continue };
            let runs = matches!(self.controllers[k].rt.as_ref(), Some(ControllerRt::NaturalDriver(a))
                if a.active && (a.lane_change_pending() || (a.changes_lane() && t > -crate::dynamics::ESMINI_SMALL_NUMBER)));
            if !runs {
                continue;
            }
            let Some(mut rt) = self.controllers.get_mut(k).and_then(|c| c.rt.take()) else { continue };
            if let ControllerRt::NaturalDriver(a) = &mut rt {
                self.step_natural_driver_action(e, a, dt);
                // the default controller stays off (hold_during_restart)
                if let Some(en) = self.entities.get_mut(e) {
                    en.moved_by_action = true;
                }
            }
            if let Some(slot) = self.controllers.get_mut(k) {
                slot.rt = Some(rt);
            }
        }
    }

    /// Step every active controller by `dt` (after the storyboard, before the default controller).
    pub(crate) fn step_controllers(&mut self, dt: f64) {
        if !self.any_controller {
            return;
        }
        for k in 0..self.controllers.len() {
            let Some(e) = self.controllers.get(k).map(|c| c.entity) else { continue };
            let Some(mut rt) = self.controllers.get_mut(k).and_then(|c| c.rt.take()) else { continue };
            match &mut rt {
                ControllerRt::Acc(a) => {
                    // Stepped after the default controller (`step_controllers_in_order`).
                    if a.active && self.entities.get(e).is_some_and(|en| en.active) {
                        self.hold_for_override(e, &mut a.moved_by_action, a.override_mode);
                    }
                }
                ControllerRt::AlksR157(a) => {
                    // Stepped after the default controller (`step_controllers_in_order`), which
                    // leaves the entity alone when the model holds the longitudinal domain.
                    if a.active && self.entities.get(e).is_some_and(|en| en.active) {
                        // (the model moves the entity whatever moved it before: what the hold notes is unused)
                        self.hold_for_override(e, &mut false, a.override_mode && a.longitudinal);
                    }
                }
                ControllerRt::NaturalDriver(a) => {
                    // Decides and moves after the default controller (`step_controllers_in_order`).
                    // Its lane change is an injected action, which ScenarioEngine::step steps
                    // whether or not the entity exists: it runs on while the entity is deleted.
                    let present = self.entities.get(e).is_some_and(|en| en.active);
                    if a.active && (present || a.changes_lane()) {
                        self.step_natural_driver_action(e, a, dt);
                    }
                }
                // Steer after the default controller moved what they follow (`step_controllers_in_order`);
                // until then the default controller leaves the entity alone.
                ControllerRt::FollowGhost(f) => self.hold_follower(e, f.active && f.longitudinal),
                ControllerRt::FollowReference(f) => self.hold_follower(e, f.active),
                // Active on the lateral domain only, the default controller moves it first.
                ControllerRt::OffroadFollower(f) => self.hold_follower(e, f.holds_longitudinal()),
                // Steps after the default controller (`step_controllers_in_order`); its running lane
                // change moves the entity instead of the default controller (esmini's override).
                ControllerRt::FollowRoute(f) => self.hold_follower(e, f.holds_entity()),
                // Steps after the default controller (`step_controllers_in_order`).
                ControllerRt::Looming(l) => {
                    let held = l.active && l.override_mode && self.entities.get(e).is_some_and(|en| en.active);
                    self.hold_follower(e, held);
                }
            }
            if let Some(slot) = self.controllers.get_mut(k) {
                slot.rt = Some(rt);
            }
        }
    }
}

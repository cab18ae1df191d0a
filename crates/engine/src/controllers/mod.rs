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

use self::state::ControllerRt;
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
    /// Runs `step` on each entity's controller in esmini's order (`step_order`), the entity
    /// being in the run: the controller is taken out of its slot meanwhile (so that `step` may
    /// use the whole simulation) and put back after. Each kind's stepping picks its own variant; `wants` says beforehand which
    /// controllers `step` acts on (its variant, active), so that the others are not moved out
    /// and back for nothing (a controller's state is large; `step` leaves them as they are).
    pub(crate) fn for_each_controller(&mut self, wants: impl Fn(&ControllerRt) -> bool, mut step: impl FnMut(&mut Self, usize, &mut ControllerRt)) {
        if !self.any_controller {
            return;
        }
        for k in 0..self.controllers.len() {
            let e = self.controller_order.get(k).copied().unwrap_or(k);
            if !self.controllers.get(e).and_then(Option::as_ref).is_some_and(&wants) {
                continue;
            }
            // esmini's ScenarioEngine::step steps every active controller whether or not its
            // entity is in the simulation. Done so for the ACC (a deleted entity's speed goes on
            // changing: fixture acc_steps_while_away.xosc); the other models wait while their
            // entity is deleted.
            let away_acc = matches!(self.controllers.get(e), Some(Some(ControllerRt::Acc(_))));
            if !away_acc && !self.entities.get(e).is_some_and(|en| en.active) {
                continue;
            }
            let Some(mut c) = self.controllers.get_mut(e).and_then(Option::take) else { continue };
            step(self, e, &mut c);
            if let Some(slot) = self.controllers.get_mut(e) {
                *slot = Some(c);
            }
        }
    }

    /// Assign controller `c` to entity `e`; warns when its type is not modelled.
    pub(crate) fn assign_controller(&mut self, e: usize, c: &Controller) {
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
                if self.net.is_some_and(|n| n.roads.iter().any(|r| r.elevation.iter().chain(&r.superelevation).any(|c| c.b != 0.0 || c.c != 0.0 || c.d != 0.0)))
                {
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
        if let Some(slot) = self.controllers.get_mut(e) {
            *slot = rt;
        }
    }

    /// ActivateControllerAction (or an AssignControllerAction that activates) on entity `e` for
    /// the given domains. esmini activates a controller on the requested domains it operates on
    /// (Controller::Activate): ACC, ALKS, NaturalDriver and Looming on the longitudinal one only.
    pub(crate) fn activate_controller(&mut self, e: usize, lateral: bool, longitudinal: bool) {
        let Some(speed) = self.entities.get(e).map(|en| en.speed) else { return };
        match self.controllers.get_mut(e) {
            Some(Some(ControllerRt::Acc(a))) => a.activate(speed, longitudinal),
            Some(Some(ControllerRt::AlksR157(a))) => a.activate(speed, lateral, longitudinal),
            Some(Some(ControllerRt::NaturalDriver(a))) => a.activate(speed, longitudinal),
            Some(Some(ControllerRt::FollowGhost(f))) => {
                if let Some(en) = self.entities.get(e) {
                    f.activate(en, longitudinal);
                }
            }
            Some(Some(ControllerRt::FollowReference(f))) => {
                let wheelbase = follow_reference::wheelbase(self.scenario, e);
                if let Some(en) = self.entities.get(e) {
                    f.activate(en, wheelbase);
                }
            }
            Some(Some(ControllerRt::FollowRoute(f))) => f.activate(longitudinal),
            Some(Some(ControllerRt::Looming(l))) => {
                if let Some(en) = self.entities.get(e) {
                    l.activate(en, longitudinal, looming::position_heading(self.net, en));
                }
                if lateral {
                    self.align_to_road_heading(e);
                }
            }
            Some(Some(ControllerRt::OffroadFollower(f))) => {
                if let Some(en) = self.entities.get(e) {
                    f.activate(en, lateral, longitudinal);
                }
            }
            _ => {}
        }
    }

    /// Whether a controller of entity `e` in override mode owns its longitudinal motion now
    /// (esmini's `Object::IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LONG)`): an
    /// active ACC/ALKS, Looming or ALKS R157 in override mode, a FollowRoute controller during
    /// its lane change.
    pub(crate) fn longitudinal_overridden(&self, e: usize) -> bool {
        if self.outside(e) {
            return true;
        }
        match self.controllers.get(e) {
            Some(Some(ControllerRt::Acc(a))) => a.overrides_longitudinal(),
            Some(Some(ControllerRt::FollowRoute(f))) => f.overrides_longitudinal(),
            Some(Some(ControllerRt::OffroadFollower(f))) => f.holds_longitudinal(),
            // ControllerLooming operates on the longitudinal domain, in override mode unless
            // its `mode` says additive.
            Some(Some(ControllerRt::Looming(l))) => l.active && l.override_mode,
            // ControllerALKS_R157SM operates on both domains (the Controller default).
            Some(Some(ControllerRt::AlksR157(a))) => a.active && a.override_mode && a.longitudinal,
            _ => false,
        }
    }

    /// Whether any active controller of entity `e` holds its longitudinal domain in override mode:
    /// esmini's `Object::IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LONG)` over every
    /// controller type: `longitudinal_overridden`'s set (the one a SpeedAction is ended under so
    /// far: ACC/ALKS, Looming, ALKS R157, OffroadFollower, FollowRoute during its lane change, an
    /// entity driven from outside) and besides a NaturalDriver unless additive and a
    /// FollowReference following an entity.
    pub(crate) fn long_domain_overridden(&self, e: usize) -> bool {
        if self.longitudinal_overridden(e) {
            return true;
        }
        match self.controllers.get(e) {
            Some(Some(ControllerRt::NaturalDriver(n))) => n.active && n.override_mode,
            Some(Some(ControllerRt::FollowReference(f))) => f.active && !f.uses_ghost(),
            _ => false,
        }
    }

    /// Whether an active controller of entity `e` in override mode owns its lateral or
    /// longitudinal motion: esmini's `Object::IsControllerModeOnAnyOfDomains(MODE_OVERRIDE,
    /// DOMAIN_MASK_LAT_AND_LONG)`, under which TeleportAction::Start does nothing. Each type's
    /// mode as esmini gives it: ACC/ALKS additive unless `mode` says override (ControllerACC);
    /// Looming, NaturalDriver and ALKS R157 override unless it says additive (the Controller
    /// base); FollowGhost and FollowReference always override; FollowRoute only while it
    /// changes lanes; an OffroadFollower on whichever domain it is active (ControllerOffroadFollower
    /// keeps the Controller base's mode, override unless a `mode` property says additive; the
    /// engine reads no `mode` for it).
    pub(crate) fn overrides_motion(&self, e: usize) -> bool {
        match self.controllers.get(e) {
            Some(Some(ControllerRt::Acc(a))) => a.overrides_longitudinal(),
            Some(Some(ControllerRt::Looming(l))) => l.active && l.override_mode,
            Some(Some(ControllerRt::NaturalDriver(n))) => n.active && n.override_mode,
            Some(Some(ControllerRt::AlksR157(a))) => a.active && a.override_mode,
            Some(Some(ControllerRt::FollowGhost(f))) => f.active,
            Some(Some(ControllerRt::FollowReference(f))) => f.active,
            Some(Some(ControllerRt::FollowRoute(f))) => f.overrides_longitudinal(),
            Some(Some(ControllerRt::OffroadFollower(f))) => f.active,
            _ => false,
        }
    }

    /// Whether an active controller of entity `e` in override mode holds its lateral domain
    /// (esmini's `IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LAT)`), under which a
    /// lane change, a lane offset or a trajectory does nothing and never ends
    /// (LatLaneChangeAction, LatLaneOffsetAction, FollowTrajectoryAction: Start and Step return
    /// early; a lateral distance action waits on the longitudinal domain instead,
    /// `long_domain_overridden`): an ALKS R157 controller activated laterally in override mode, an
    /// OffroadFollower, a FollowReference following another entity. (ACC, ALKS, Looming and
    /// NaturalDriver operate on the longitudinal domain only; a ghost follower's actions drive
    /// its ghost.)
    pub(crate) fn lateral_overridden(&self, e: usize) -> bool {
        match self.controllers.get(e) {
            Some(Some(ControllerRt::AlksR157(a))) => a.active && a.override_mode && a.lateral,
            Some(Some(ControllerRt::OffroadFollower(f))) => f.holds_lateral(),
            Some(Some(ControllerRt::FollowReference(f))) => f.active && !f.uses_ghost(),
            _ => false,
        }
    }

    /// Step every active controller by `dt` (after the storyboard, before the default controller).
    pub(crate) fn step_controllers(&mut self, dt: f64) {
        if !self.any_controller {
            return;
        }
        for e in 0..self.controllers.len() {
            let Some(mut rt) = self.controllers.get_mut(e).and_then(|c| c.take()) else { continue };
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
                        self.hold_for_override(e, &mut a.moved_by_action, a.override_mode && a.longitudinal);
                    }
                }
                ControllerRt::NaturalDriver(a) => {
                    // Decides and moves after the default controller (`step_controllers_in_order`).
                    if a.active && self.entities.get(e).is_some_and(|en| en.active) {
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
            if let Some(slot) = self.controllers.get_mut(e) {
                *slot = Some(rt);
            }
        }
    }
}

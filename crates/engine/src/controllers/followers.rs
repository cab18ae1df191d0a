//! Stepping the controllers that follow another entity (FollowGhost, FollowReference). esmini
//! steps controllers after its default controller has moved every entity, so the ghost or the
//! reference has already moved when its follower steers: they step after the default
//! controller, where `step_controllers` only keeps the default controller off the follower.

use super::kinematic_vehicle::KinematicVehicle;
use super::ControllerRt;
use crate::sim::Sim;

impl<'a> Sim<'a> {
    /// Step every active follower by `dt` (after the default controller).
    pub(crate) fn step_followers(&mut self, dt: f64) {
        if !self.any_controller {
            return;
        }
        for e in 0..self.controllers.len() {
            let is_follower = matches!(self.controllers.get(e), Some(Some(ControllerRt::FollowGhost(_) | ControllerRt::FollowReference(_))));
            if !is_follower || !self.entities.get(e).is_some_and(|en| en.active) {
                continue;
            }
            let Some(mut rt) = self.controllers.get_mut(e).and_then(|c| c.take()) else { continue };
            match &mut rt {
                ControllerRt::FollowGhost(f) if f.active => self.step_follow_ghost(e, f, dt),
                ControllerRt::FollowReference(f) if f.active => self.step_follow_reference(e, f, dt),
                _ => {}
            }
            if let Some(slot) = self.controllers.get_mut(e) {
                *slot = Some(rt);
            }
        }
    }

    /// Put follower `e` where its vehicle model drove it; false (nothing changed) when the
    /// model's state is not finite (absurd gains: stop driving rather than write such a pose).
    pub(super) fn place_driven(&mut self, e: usize, car: &KinematicVehicle) -> bool {
        if !car.is_finite() {
            return false;
        }
        let net = self.net;
        if let Some(en) = self.entities.get_mut(e) {
            let z = if net.is_some() { None } else { Some(en.z) };
            en.set_world(net, car.x, car.y, z, car.h);
            en.speed = car.speed;
            en.moved_by_action = true;
        }
        true
    }

    /// Before the default controller, for a controller that may override it (ACC, looming):
    /// remember in `moved_by_action` whether an action moved entity `e`, and in override mode
    /// keep the default controller from moving it (the controller does).
    pub(super) fn hold_for_override(&mut self, e: usize, moved_by_action: &mut bool, override_mode: bool) {
        let Some(en) = self.entities.get_mut(e) else { return };
        *moved_by_action = en.moved_by_action;
        if override_mode {
            en.moved_by_action = true;
        }
    }

    /// Keep the default controller off follower `e` while its controller is `active`.
    pub(super) fn hold_follower(&mut self, e: usize, active: bool) {
        if let Some(en) = self.entities.get_mut(e).filter(|_| active) {
            en.moved_by_action = true;
        }
    }
}

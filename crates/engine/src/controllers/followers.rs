//! Stepping the controllers that follow another entity (FollowGhost, FollowReference). esmini
//! steps controllers after its default controller has moved every entity, so the ghost or the
//! reference has already moved when its follower steers: they step after the default
//! controller, where `step_controllers` only keeps the default controller off the follower.

use super::ControllerRt;
use crate::sim::Sim;

impl<'a> Sim<'a> {
    /// Step every active follower by `dt` (after the default controller).
    pub fn step_followers(&mut self, dt: f64) {
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

    /// Keep the default controller off follower `e` while its controller is `active`.
    pub(super) fn hold_follower(&mut self, e: usize, active: bool) {
        if let Some(en) = self.entities.get_mut(e).filter(|_| active) {
            en.moved_by_action = true;
        }
    }
}

//! What the controllers that drive their entity themselves share (FollowGhost,
//! FollowReference, OffroadFollower, ACC, looming): esmini steps controllers after its default
//! controller has moved every entity (`step_order`), so the ghost or the reference has already
//! moved when its follower steers; before that, `step_controllers` only keeps the default
//! controller off the entity (`hold_follower`, `hold_for_override`), and the model's pose is
//! written back by `place_driven`.

use super::kinematic_vehicle::KinematicVehicle;
use crate::sim::Sim;

impl<'a> Sim<'a> {
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
            // The controller's Position::SetInertiaPos locates the point afresh, end-of-road
            // status included: the next step's end-of-road test reads it.
            if let Some(status) = net.and_then(|net| en.end_status_from_world(net)) {
                en.road_end_after_controller = Some(status);
            }
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

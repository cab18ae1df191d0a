//! The order in which the controllers step after the default controller has moved the entities.
//! esmini's ScenarioEngine::step walks `ScenarioReader::controller_` once and steps each active
//! controller in turn, whatever its type; that list holds the controllers in the order they were
//! made, the entities' ObjectControllers in the order the entities are declared. So a controller
//! sees the entities that an earlier controller of the list moved this step where they are now,
//! and those of a later one where they were: an OffroadFollower behind an ALKS R157 car declared
//! before it follows the car's new position, one declared after it the old one. An
//! AssignControllerAction's controller is made when the scenario is read
//! (ScenarioReader::parseOSCPrivateAction pushes it onto `controller_`), after every
//! ObjectController, in the order the actions are written: it steps after those.

use super::state::ControllerRt;
use crate::sim::Sim;

/// More ObjectControllers than any scenario has: the ranks of the assigned controllers start here.
const OBJECT_CONTROLLERS_MAX: usize = usize::MAX / 2;

impl<'a> Sim<'a> {
    /// esmini's place in `controller_` of a controller: an ObjectController's is its index
    /// among them (entity order), an AssignControllerAction's (action slot `slot`) comes after
    /// every ObjectController, in the order the actions are written (the slots' order).
    pub(crate) fn controller_rank(&self, assigned_by: Option<usize>) -> usize {
        match assigned_by {
            None => self.controllers.iter().filter(|c| c.assigned_by.is_none()).count(),
            Some(slot) => OBJECT_CONTROLLERS_MAX + slot,
        }
    }

    /// Step every active controller by `dt`, in esmini's order (ScenarioEngine::step's loop over
    /// `controller_`). In frame 0 (`frame0`, dt 0) esmini steps
    /// them too (a FollowReference's placement then turns its heading on a banked road, as
    /// every SetInertiaPos does); the ghost followers are left out there, their ghost not yet
    /// having a trail.
    pub(crate) fn step_controllers_in_order(&mut self, dt: f64, frame0: bool) {
        // The engine's stop at a road's end comes before every controller's step.
        self.for_each_controller(
            |c| matches!(c, ControllerRt::Acc(a) if a.active),
            |sim, e, c| {
                if let ControllerRt::Acc(a) = c {
                    sim.acc_stop_at_road_end(e, a);
                }
            },
        );
        self.for_each_controller(
            |c| match c {
                ControllerRt::FollowGhost(f) => f.active && !frame0,
                ControllerRt::FollowReference(f) => f.active,
                ControllerRt::OffroadFollower(f) => f.active,
                ControllerRt::Acc(a) => a.active,
                ControllerRt::AlksR157(a) => a.active,
                ControllerRt::Looming(l) => l.active,
                ControllerRt::FollowRoute(f) => f.active,
                ControllerRt::NaturalDriver(n) => n.active,
            },
            |sim, e, c| match c {
                ControllerRt::FollowGhost(f) => sim.step_follow_ghost(e, f, dt),
                ControllerRt::FollowReference(f) => sim.step_follow_reference(e, f, dt),
                ControllerRt::OffroadFollower(f) => sim.step_offroad_follower(e, f, dt),
                ControllerRt::Acc(a) => sim.step_acc(e, a, dt),
                ControllerRt::AlksR157(a) => sim.step_alks_r157(e, a, dt),
                ControllerRt::Looming(l) => sim.step_looming(e, l, dt),
                ControllerRt::FollowRoute(f) => sim.step_follow_route(e, f, dt),
                ControllerRt::NaturalDriver(n) => sim.step_natural_driver(e, n, dt),
            },
        );
    }
}

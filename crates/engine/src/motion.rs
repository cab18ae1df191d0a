//! The default controller and the bookkeeping after each move: an entity no action moved keeps
//! its lane and lateral offset and drives on along the road network at its speed (straight
//! ahead when there is no road); then speed-derived quantities, odometer and the timers of the
//! stand-still, off-road and end-of-road conditions are updated.

use crate::angles::wrap;
use crate::dynamics::{ESMINI_SMALL_NUMBER, SMALL};
use crate::ghost::state::GhostMode;
use crate::roads::{move_along_route_drawing, MoveStatus};
use crate::sim::Sim;

/// Below this speed an entity stands still (esmini's threshold), m/s.
const STAND_STILL: f64 = 1e-3;

/// The state before a step, to derive rates from.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Before {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub h: f64,
    pub speed: f64,
}

impl<'a> Sim<'a> {
    /// Move every entity no action moved this step by speed · dt.
    pub(crate) fn default_controller(&mut self, dt: f64) {
        let net = self.net;
        let random = &mut self.random;
        for en in &mut self.entities {
            if let Some(status) = en.road_end_after_controller.take() {
                en.at_road_end = status;
            }
            // A teleport keeps the position status (Position::TeleportTo copies the location
            // only, CopyLocation leaves `status_`), and ScenarioEngine::step checks it after
            // the (here skipped) default move: an entity stuck at a dead end and teleported
            // away stays stopped, whatever speed an action set meanwhile. So does one added
            // back (AddEntityAction::Start teleports it the same way).
            if (en.teleported || en.appeared) && en.active && !en.outside && !en.roadless {
                en.stop_if_stuck_at_road_end();
            }
            // ScenarioEngine::step: no default move at |speed| <= SMALL_NUMBER (1e-6). Its
            // end-of-road test follows for every object all the same, moved or not: one an
            // action or a controller moved, or one standing at a dead end, is stopped too, its
            // speed applied, so none is measured from an action's sideways jump there.
            if !en.active || en.outside || en.moved_by_action || en.speed.abs() <= ESMINI_SMALL_NUMBER {
                if en.active && !en.outside && !en.roadless {
                    en.stop_if_stuck_at_road_end();
                }
                continue;
            }
            if en.roadless {
                // esmini's position without a road: the move along it fails with the end-of-road
                // status, and from the next step the entity is stopped (ScenarioEngine::step).
                if en.at_road_end {
                    en.speed = 0.0;
                }
                en.at_road_end = true;
                continue;
            }
            // ScenarioEngine::defaultController marks the speed as applied.
            en.speed_set = true;
            if en.route_broken && en.route.is_some() {
                // Position::MoveAlongS: the route move fails (ERROR_GENERIC, the route's first
                // waypoint has no direction) before the entity moves; defaultController stops it.
                en.speed = 0.0;
                continue;
            }
            match (net, en.lane) {
                (Some(net), Some(mut lp)) => {
                    // esmini's own move: a junction tie is decided by its generator.
                    let pedestrian = en.kind == crate::entities::EntityKind::Pedestrian;
                    let status = move_along_route_drawing(net, &mut lp, en.speed * dt, en.route.as_deref(), random, pedestrian);
                    en.set_lane_pos(net, lp);
                    // Position::MoveAlongS leaves the end-of-road status after a move that fails
                    // at a dead end, and also after one that ends within SMALL_NUMBER of an end
                    // without a link element (an arrival exactly there).
                    if status == MoveStatus::EndOfRoad || crate::roads::past_end::unlinked_end_at(net, lp.road, lp.s) {
                        // ScenarioEngine::step, after the default controller's move: an entity
                        // already flagged at the end of the road (`end_of_road`, set after the
                        // step that reached it) whose velocity is zero (`vel` is still the last
                        // step's: the step after the arrival, stuck) is stopped. So the speed
                        // drops two steps after the arrival, not one (a SpeedCondition sees it).
                        en.at_road_end = true;
                        en.stop_if_stuck_at_road_end();
                    } else {
                        en.at_road_end = false;
                    }
                }
                // Without a road network there is no road to drive along: esmini's default
                // controller leaves the entity where it is and stops it (trailer_connect).
                (None, _) => en.speed = 0.0,
                _ => {
                    en.x += en.speed * dt * en.h.cos();
                    en.y += en.speed * dt * en.h.sin();
                }
            }
        }
    }

    /// Update derived quantities after the moves of a step of length `dt`.
    pub(crate) fn after_move(&mut self, before: &[Before], dt: f64) {
        let (time, clock) = (self.time, self.clock);
        // ScenarioEngine::prepareStep measures no motion of a ghost restarted in this step
        // (RESTART mode): no odometer, rates or stored old state, so the next step measures
        // the jump back to its entity as travel (its odometer counts it) — `snapshot` in
        // `run.rs` keeps the ghost's state from before this step.
        let restarted = self.ghost.as_mut().and_then(|g| {
            g.unmeasured = g.mode == GhostMode::Restart;
            g.unmeasured.then_some(g.entity)
        });
        // ScenarioEngine::prepareGroundTruth: an entity whose speed nothing set this step gets
        // the length of its displacement over the step as its speed. The default controller
        // leaves a standing entity alone (ScenarioEngine::step moves none at |speed| <=
        // SMALL_NUMBER), so a standing car a lateral action moves sideways takes that sideways
        // rate as speed and drives off at it from the next step. Trailers get their tow
        // vehicle's speed, and the entities an active controller drives are left to it (it sets
        // the speed in every step: `ControllerRt::sets_speed`); an assigned controller that is
        // off (or on no domain it operates on) sets nothing. Asked in the loop below, before it
        // changes the entity's speed.
        let (links, controllers) = (&self.trailers.links, &self.controllers);
        let derives_speed = |i: usize, en: &crate::entities::Entity| {
            !en.speed_set
                && en.active
                && !en.outside
                && en.speed.abs() <= ESMINI_SMALL_NUMBER
                && !links.contains(&Some(i))
                && !controllers.iter().any(|c| c.entity == i && c.rt.as_ref().is_some_and(|c| c.sets_speed()))
        };
        // While the ghost runs ahead (RESTARTING), ScenarioEngine::prepareGroundTruth measures
        // the motion of the ghost only: the others, held, keep the velocity they had (frame 0's,
        // from their speed and heading, at the start), so a controller stepping right after the
        // head start sees them moving, not standing.
        let held = self.ghost.as_ref().filter(|g| g.mode == GhostMode::Restarting && dt > 0.0).map(|g| g.entity);
        for (i, (en, b)) in self.entities.iter_mut().zip(before).enumerate() {
            // ScenarioEngine::prepareGroundTruth measures the active entities only: a deleted
            // one keeps its last state (`snapshot` in run.rs) and its "teleported" mark.
            if !en.active {
                continue;
            }
            let (dx, dy) = (en.x - b.x, en.y - b.y);
            let old_vel = en.vel;
            let old_vel_z = en.vel_z;
            // An entity added back is measured from where it was last active (AddEntityAction
            // moves its position without a teleport mark): its jump is travel, and a standing
            // one takes jump / dt as its speed and drives off at it. One never active before
            // still has the mark Entities::addObject gave it ("virgin location"): a teleport.
            let appeared = std::mem::take(&mut en.appeared);
            if held.is_some_and(|g| g != i) && !en.teleported && !appeared {
                // not measured this frame
            } else if restarted == Some(i) {
                // The dirty bits are cleared all the same: the teleport does not carry over.
                en.teleported = false;
            } else if en.teleported {
                // ScenarioEngine::prepareStep/step: a teleport is no travel
                en.teleported = false;
                // (a teleport's velocity has no vertical part)
                en.vel = (en.speed * en.h.cos(), en.speed * en.h.sin());
                en.vel_z = 0.0;
                if dt > SMALL {
                    en.accel = (en.speed - b.speed) / dt;
                    en.acc_vec = ((en.vel.0 - old_vel.0) / dt, (en.vel.1 - old_vel.1) / dt);
                    en.acc_z = -old_vel_z / dt;
                    en.yaw_rate = wrap(en.h - b.h) / dt;
                }
            } else {
                en.odometer += (dx * dx + dy * dy).sqrt();
                if dt > SMALL {
                    en.vel = (dx / dt, dy / dt);
                    en.vel_z = (en.z - b.z) / dt;
                    if derives_speed(i, en) {
                        en.speed = dx.hypot(dy) / dt;
                    }
                    en.accel = (en.speed - b.speed) / dt;
                    en.acc_vec = ((en.vel.0 - old_vel.0) / dt, (en.vel.1 - old_vel.1) / dt);
                    en.acc_z = (en.vel_z - old_vel_z) / dt;
                    en.yaw_rate = wrap(en.h - b.h) / dt;
                }
            }
            // ScenarioEngine::step stamps these on its accumulated clock (`Sim::clock`), and
            // Object::IsEndOfRoad / IsStandStill / IsOffRoad read a time stamp at or below
            // SMALL_NUMBER as "no": an entity standing or off the road from the start is noted
            // so at the next step, and a ghost reaching a road's end during its head start
            // (negative time) is stamped anew every step and never counts as there, so its
            // speed is not zeroed (`stop_if_stuck_at_road_end`) before time 0 is passed.
            let stamp = (clock > crate::dynamics::ESMINI_SMALL_NUMBER).then_some(clock);
            if en.at_road_end && !en.end_of_road {
                en.end_of_road = stamp.is_some();
                en.end_of_road_since = time;
            } else if !en.at_road_end {
                en.end_of_road = false;
            }
            if en.speed.abs() >= STAND_STILL {
                en.standstill_since = None;
            } else if en.standstill_since.is_none() {
                en.standstill_since = stamp;
            }
            if en.on_road || en.lane.is_none() && self.net.is_none() {
                en.offroad_since = None;
            } else if en.offroad_since.is_none() {
                en.offroad_since = stamp;
            }
        }
    }
}

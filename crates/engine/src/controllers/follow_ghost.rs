//! FollowGhostController, as esmini has it: the storyboard's actions drive a ghost copy of the
//! entity that starts `headstartTime` seconds early (see `ghost`); the entity itself, in
//! override mode (activated laterally only, esmini's default controller moves it along its
//! lane before the controller measures), follows the ghost's trail with a simple driver model. In
//! `position` mode it finds the trail point nearest to itself, takes the ghost's speed at
//! `max(minLookaheadSpeed, lookaheadSpeed · speed)` metres further along the trail as its
//! target speed and steers towards the trail point `max(minLookaheadSteering,
//! lookaheadSteering · speed)` metres ahead (searches as esmini's, `ghost::trail`: when the
//! steering point runs past the trail's end the nearest point sticks near that end, and the
//! speed point becomes the ghost's latest sample); in `time` mode both points are where the ghost
//! was `headstartTime` minus the look-ahead (in seconds) ago. The body is esmini's kinematic
//! vehicle (`kinematic_vehicle`) with 10 m/s² and 100 m/s limits.

pub(crate) mod state;

use state::{FollowGhostRt, FollowMode};

use super::kinematic_vehicle::KinematicVehicle;
use crate::entities::Entity;
use crate::ghost::trail::TrailPoint;
use crate::sim::Sim;
use openscenario::Controller;

/// Acceleration limit and gain of the driver model, m/s².
const MAX_ACC: f64 = 10.0;
/// Speed limit of the driver model, m/s.
const MAX_SPEED: f64 = 100.0;
/// Longest head start simulated, s.
const MAX_HEADSTART: f64 = 600.0;

impl FollowGhostRt {
    pub(crate) fn new(c: &Controller) -> FollowGhostRt {
        let num = |n: &str, d: f64| c.properties.get(n).and_then(|v| v.trim().parse::<f64>().ok()).filter(|v| v.is_finite()).unwrap_or(d);
        let mode = match c.properties.get("followMode").map(str::trim) {
            Some("position") => FollowMode::Position,
            _ => FollowMode::Time,
        };
        FollowGhostRt {
            active: false,
            // Capped: the head start is simulated before time 0 (hostile input).
            headstart: num("headstartTime", 3.0).clamp(0.0, MAX_HEADSTART),
            mode,
            lookahead_speed: num("lookaheadSpeed", 0.1),
            min_lookahead_speed: num("minLookaheadSpeed", 0.1),
            lookahead_steering: num("lookaheadSteering", 1.0),
            min_lookahead_steering: num("minLookaheadSteering", 1.0),
            steering_scale: num("steeringSpeedInertia", 0.01),
            vehicle: None,
            longitudinal: true,
            follow_index: 0,
            closest_s: 0.0,
        }
    }

    /// Switched on (on the longitudinal domain too or not): the driver model starts from the
    /// entity's pose and speed.
    pub(crate) fn activate(&mut self, en: &Entity, longitudinal: bool) {
        self.active = true;
        self.longitudinal = longitudinal;
        self.vehicle = Some(KinematicVehicle::new(en.x, en.y, en.h, en.speed, en.bbox[3], MAX_SPEED));
    }
}

impl<'a> Sim<'a> {
    /// One step of the follower `e` (after the ghost moved this step).
    pub(super) fn step_follow_ghost(&mut self, e: usize, f: &mut FollowGhostRt, dt: f64) {
        let (Some(ghost), Some(mut car)) = (self.ghost.as_ref().filter(|g| g.owner == e), f.vehicle) else { return };
        // ControllerFollowGhost::Step measures from the entity's position and heading and
        // drives the body from its own. Active laterally only, the default controller has moved
        // the entity along its lane first; and the heading is the one the entity's position
        // holds (SetInertiaPos turned the body's by a banked road's rotation).
        let Some(en) = self.entities.get(e) else { return };
        let (x, y, h, speed) = (en.x, en.y, en.h, car.speed);
        let trail = &ghost.trail;
        let (speed_point, steer_point): (Option<TrailPoint>, Option<TrailPoint>) = match f.mode {
            FollowMode::Position => {
                // ControllerFollowGhost::Step: the nearest point is searched from the segment
                // the last steering point lay on; when nothing was searched, the old arc
                // length stays. The speed point is looked up from that segment without moving
                // it; the steering point is looked up from the trail's start and its segment
                // (the last vertex when it ran past the end) is where the next search starts.
                if let Some((p, i)) = trail.closest(x, y, f.follow_index) {
                    f.closest_s = p.s;
                    f.follow_index = i;
                }
                let sp = trail.at_s(f.closest_s + f.min_lookahead_speed.max(f.lookahead_speed * speed), f.follow_index);
                let st = trail.at_s(f.closest_s + f.min_lookahead_steering.max(f.lookahead_steering * speed), 0);
                if let Some((_, i)) = st {
                    f.follow_index = i;
                }
                (sp.map(|(p, _)| p), st.map(|(p, _)| p))
            }
            FollowMode::Time => {
                // Both look-ups start from, and move, the same segment index.
                let back = self.time - f.headstart;
                let sp = trail.at_time(back + f.min_lookahead_speed.max(f.lookahead_speed), f.follow_index);
                if let Some((_, i)) = sp {
                    f.follow_index = i;
                }
                let st = trail.at_time(back + f.min_lookahead_steering.max(f.lookahead_steering), f.follow_index);
                if let Some((_, i)) = st {
                    f.follow_index = i;
                }
                (sp.map(|(p, _)| p), st.map(|(p, _)| p))
            }
        };
        let (target_speed, tx, ty) = match (speed_point, steer_point) {
            (Some(sp), Some(st)) => (sp.speed, st.x, st.y),
            // In position mode an empty trail (the step a restart cleared it, TeleportAction::
            // Start) is no error to esmini's FindPointAhead (it says "past the end"): the points
            // stay default TrajVertex values, so the car steers at the world origin with target
            // speed 0, and the segment index is left undefined (the next search starts at 0).
            _ if f.mode == FollowMode::Position && trail.vertices.is_empty() => {
                f.follow_index = 0;
                (0.0, 0.0, 0.0)
            }
            _ => (0.0, x, y),
        };
        // Heading error to the steering point: asin of the cross product of unit vectors.
        let (dx, dy) = (tx - x, ty - y);
        let len = dx.hypot(dy);
        let (ux, uy) = if len > crate::dynamics::SMALL { (dx / len, dy / len) } else { (0.0, 0.0) };
        let cross = h.cos() * uy - h.sin() * ux;
        let heading_error = cross.clamp(-1.0, 1.0).asin();
        car.drive_to_target(dt, target_speed, heading_error, MAX_ACC, f.steering_scale);
        if self.place_driven(e, &car) {
            f.vehicle = Some(car);
        }
    }
}

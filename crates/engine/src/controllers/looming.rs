//! LoomingController, esmini's driver model that steers by the looming of the road and the car
//! ahead (ControllerLooming): a near point 10 m ahead on the lane centre and a far point (the
//! tangent point of the lane's inner edge within 80 m, else the lead vehicle within 80 m, else
//! the lane centre 80 m ahead) drive a steering law on esmini's kinematic vehicle, and an
//! ACC-like rule drives its throttle.
//!
//! Modelled here: the longitudinal part exactly as ControllerLooming::Step has it — the lead
//! vehicle (nearest in the lane within 130 m along the road, lateral offset below 5 m, gap
//! between the bounding boxes), the throttle `distFactor − distFactor·dvSet −
//! (1 − distFactor)·dvMin` (or `setSpeed − speed` without a lead), clamped to ±1, and
//! vehicle::Vehicle::DrivingControlAnalog's speed (max acceleration or deceleration times the
//! throttle, an engine drag of 0.1 % per step at zero throttle, a handbrake when braking
//! through zero). Not modelled: the steering (it needs esmini's OSI points of the lane edges
//! for the tangent point); the entity keeps its lane, which the run says in a warning.

use crate::roads::move_along_s;
use crate::sim::Sim;
use openscenario::Controller;

/// Minimum gap to the lead vehicle, m (ControllerLooming::Step `minDist`).
const MIN_DIST: f64 = 3.0;
/// How far along the road a lead vehicle is looked for, m.
const LOOKAHEAD: f64 = 130.0;
/// Largest lateral offset of a lead vehicle, m.
const MIN_LATERAL_DIST: f64 = 5.0;
/// vehicle.cpp: ENGINE_BRAKE_FACTOR_DEFAULT, MAX_SPEED_DEFAULT.
const ENGINE_BRAKE_FACTOR: f64 = 0.001;
const VEHICLE_MAX_SPEED: f64 = 70.0;
/// CommonMini's SMALL_NUMBER.
const SMALL_NUMBER: f64 = 1e-6;
const LARGE: f64 = 1e10;

/// What the run says about a LoomingController.
pub const APPROXIMATION: &str = "LoomingController: its speed follows esmini's looming rule, but its steering (near point 10 m ahead, far tangent point of the lane edge within 80 m on esmini's OSI points, kinematic vehicle) is not modelled: the entity keeps its lane centre, where esmini's drifts up to about a metre in curves";

#[derive(Debug, Clone)]
pub struct LoomingRt {
    pub active: bool,
    time_gap: f64,
    set_speed: f64,
    set_speed_given: bool,
    override_mode: bool,
    /// The speed of esmini's vehicle model (vehicle_.speed_), kept by the controller.
    speed: f64,
    handbrake: bool,
    max_acc: f64,
    max_dec: f64,
    /// An action moved the entity this step (seen before the default controller ran).
    moved_by_action: bool,
}

impl LoomingRt {
    /// ControllerLooming's constructor: `timeGap` (1.5 s) and `setSpeed` properties; the mode
    /// is esmini's Controller default, override, unless `mode` says additive.
    pub fn new(c: &Controller) -> LoomingRt {
        let num = |n: &str| c.properties.get(n).and_then(|v| v.trim().parse::<f64>().ok());
        LoomingRt {
            active: false,
            time_gap: num("timeGap").unwrap_or(1.5),
            set_speed: num("setSpeed").unwrap_or(0.0),
            set_speed_given: num("setSpeed").is_some(),
            override_mode: c.properties.get("mode") != Some("additive"),
            speed: 0.0,
            handbrake: false,
            max_acc: 0.0,
            max_dec: 0.0,
            moved_by_action: false,
        }
    }

    /// ControllerLooming::Activate: the vehicle model starts at the entity's speed; the set
    /// speed is the entity's speed unless given in override mode. The controller operates on
    /// the longitudinal domain only.
    pub fn activate(&mut self, speed: f64, max_acc: f64, max_dec: f64, longitudinal: bool) {
        if !longitudinal {
            return;
        }
        self.active = true;
        if !self.override_mode || !self.set_speed_given {
            self.set_speed = speed;
        }
        self.speed = speed;
        self.handbrake = false;
        self.max_acc = max_acc;
        self.max_dec = max_dec;
    }

    /// vehicle::Vehicle::DrivingControlAnalog, the throttle part.
    fn drive(&mut self, dt: f64, throttle: f64) {
        let old = self.speed;
        if self.handbrake {
            if throttle.abs() < SMALL_NUMBER || throttle > SMALL_NUMBER {
                self.handbrake = false;
            }
            return;
        }
        self.speed += if throttle < 0.0 { self.max_dec } else { self.max_acc } * throttle * dt;
        if old > 0.0 && self.speed < 0.0 {
            self.speed = 0.0;
            self.handbrake = true;
        } else {
            if throttle.abs() < SMALL_NUMBER {
                self.speed *= 1.0 - ENGINE_BRAKE_FACTOR;
            }
            self.speed = self.speed.clamp(-VEHICLE_MAX_SPEED, VEHICLE_MAX_SPEED);
        }
    }
}

impl<'a> Sim<'a> {
    /// Before the default controller: in override mode keep it from moving the entity.
    pub(super) fn hold_for_looming(&mut self, e: usize, l: &mut LoomingRt) {
        let Some(en) = self.entities.get_mut(e) else { return };
        l.moved_by_action = en.moved_by_action;
        if l.override_mode {
            en.moved_by_action = true;
        }
    }

    /// Step every active LoomingController by `dt`, after the default controller (esmini steps
    /// its controllers then, in frame 0 too with dt = 0).
    pub fn step_looming_controllers(&mut self, dt: f64) {
        if !self.any_controller {
            return;
        }
        for e in 0..self.controllers.len() {
            if !matches!(self.controllers.get(e), Some(Some(super::ControllerRt::Looming(_)))) {
                continue;
            }
            let Some(Some(super::ControllerRt::Looming(mut l))) = self.controllers.get_mut(e).map(Option::take) else { continue };
            if l.active && self.entities.get(e).is_some_and(|en| en.active) {
                self.step_looming(e, &mut l, dt);
            }
            if let Some(slot) = self.controllers.get_mut(e) {
                *slot = Some(super::ControllerRt::Looming(l));
            }
        }
    }

    /// ControllerLooming::Step, its longitudinal part.
    fn step_looming(&mut self, e: usize, l: &mut LoomingRt, dt: f64) {
        let Some(me) = self.entities.get(e) else { return };
        let current = me.speed;
        let mut min_gap = LARGE;
        let mut lead: Option<usize> = None;
        for (i, p) in self.entities.iter().enumerate() {
            if i == e || !p.active {
                continue;
            }
            let (Some(net), Some(la), Some(lb)) = (self.net, me.lane, p.lane) else { continue };
            // Position::Delta, reference point to reference point, then the bounding boxes.
            let Some((ds, same_lane, dt_lat)) = super::acc::lane_delta(net, la, lb, LOOKAHEAD) else { continue };
            if ds.abs() > LOOKAHEAD {
                continue;
            }
            let dh = crate::roads::road_follow::wrap(me.h - p.h).abs();
            let front = me.bbox[3] / 2.0 + me.bbox[0];
            let back = if dh < std::f64::consts::FRAC_PI_2 { p.bbox[3] / 2.0 - p.bbox[0] } else { p.bbox[3] / 2.0 + p.bbox[0] };
            let gap = ds - front - back;
            if same_lane && gap > 0.0 && gap < min_gap && dt_lat.abs() < MIN_LATERAL_DIST {
                min_gap = gap;
                lead = Some(i);
            }
        }
        let acc = match lead.and_then(|i| self.entities.get(i)) {
            Some(_) if min_gap < 1.0 => 0.0,
            Some(ld) => {
                let follow = MIN_DIST + l.time_gap * current.max(ld.speed).abs();
                let dist_factor = ((min_gap - follow) / follow).min(1.0);
                let dv_min = current - l.set_speed.min(ld.speed);
                let dv_set = current - l.set_speed;
                dist_factor - dist_factor * dv_set - (1.0 - dist_factor) * dv_min
            }
            None => l.set_speed - current,
        };
        l.drive(dt, acc.clamp(-1.0, 1.0));
        let net = self.net;
        let Some(en) = self.entities.get_mut(e) else { return };
        if l.override_mode && !l.moved_by_action {
            // Approximation: along the lane instead of esmini's steered vehicle.
            match (net, en.lane) {
                (Some(net), Some(mut lp)) => {
                    let status = move_along_s(net, &mut lp, l.speed * dt);
                    en.set_lane_pos(net, lp);
                    // ScenarioEngine::step: the position's end-of-road status
                    en.at_road_end = status == crate::roads::MoveStatus::EndOfRoad;
                }
                _ => {
                    en.x += l.speed * dt * en.h.cos();
                    en.y += l.speed * dt * en.h.sin();
                }
            }
            en.moved_by_action = true;
        }
        en.speed = l.speed;
    }
}

//! FollowReferenceController, as esmini has it: the entity, in override mode on both domains,
//! tracks a reference entity — `referenceEntity`, or by default a ghost copy of itself that
//! runs the storyboard's actions (see `ghost`, no head start). Steering is a Stanley
//! controller: heading gain · heading error (sign of the speed) + atan2(cross-track gain ·
//! lateral error of the front axle (rear axle when reversing), speed stabiliser + speed) +
//! curvature gain · atan(curvature · wheelbase), the curvature being the reference's yaw rate
//! (limited to 0.5 rad/s) over its speed. The speed follows a critically damped spring on the
//! longitudinal distance to the reference: −k·dx − 2√k·(v − v_ref). The body is esmini's
//! kinematic vehicle (`kinematic_vehicle`).

pub(crate) mod state;

use state::FollowReferenceRt;

use super::kinematic_vehicle::KinematicVehicle;
use crate::angles::angle_pi;
use crate::entities::Entity;
use crate::sim::Sim;
use openscenario::{Controller, EntityObject};

/// esmini's SMALL_NUMBER (1e-6, CommonMini.hpp): the reference's speed is floored to it for
/// the curvature (`ABS_FLOOR`).
const SMALL: f64 = crate::dynamics::ESMINI_SMALL_NUMBER;
/// Yaw rates beyond this do not count for the reference's curvature, rad/s.
const MAX_YAW_RATE: f64 = 0.5;

impl FollowReferenceRt {
    pub(crate) fn new(c: &Controller) -> FollowReferenceRt {
        let num = |n: &str| c.properties.get(n).and_then(|v| v.trim().parse::<f64>().ok()).filter(|v| v.is_finite()).unwrap_or(1.0);
        FollowReferenceRt {
            active: false,
            cross_track_gain: num("stanleyCrossTrackErrorGain"),
            speed_stabilizer: num("stanleySpeedStabilizer"),
            heading_gain: num("stanleyHeadingGain"),
            curvature_gain: num("stanleyCurvatureGain"),
            stiffness: num("speedControlStiffness").max(0.0),
            reference_name: c.properties.get("referenceEntity").map(str::trim).filter(|s| !s.is_empty()).map(str::to_string),
            vehicle: None,
            wheelbase: 0.0,
        }
    }

    /// Whether it needs a ghost (no reference entity named).
    pub(crate) fn uses_ghost(&self) -> bool {
        self.reference_name.is_none()
    }

    /// Switched on: the body starts from the entity's pose and speed; `wheelbase` is the front
    /// axle's distance ahead of the reference point.
    pub(crate) fn activate(&mut self, en: &Entity, wheelbase: f64) {
        self.active = true;
        self.wheelbase = wheelbase;
        self.vehicle = Some(KinematicVehicle::new(en.x, en.y, en.h, en.speed, en.bbox[3], en.max_speed));
    }
}

/// The front axle's distance ahead of the reference point of scenario entity `e`.
pub(crate) fn wheelbase(scenario: &openscenario::Scenario, e: usize) -> f64 {
    match scenario.entities.get(e).map(|m| &m.object) {
        Some(EntityObject::Vehicle(v)) => v.axles.front.map_or(0.0, |a| a.position_x),
        _ => 0.0,
    }
}

impl<'a> Sim<'a> {
    /// Warn about FollowReference controllers whose `referenceEntity` does not exist (esmini
    /// quits; here the entity stands still).
    pub(crate) fn check_follow_references(&mut self) {
        for k in 0..self.controllers.len() {
            let Some(slot) = self.controllers.get(k) else { continue };
            let e = slot.entity;
            let Some(super::state::ControllerRt::FollowReference(f)) = &slot.rt else { continue };
            let Some(name) = f.reference_name.clone() else { continue };
            if self.entity_index(&name).is_none() {
                if let Some(m) = self.scenario.entities.get(e) {
                    let msg = format!("entity `{}`: FollowReferenceController's reference entity `{name}` does not exist; the entity stands still", m.name);
                    self.warnings.push(crate::Diagnostic::at(&m.origin, msg));
                }
            }
        }
    }

    /// One step of the follower `e` (after the reference moved this step).
    pub(super) fn step_follow_reference(&mut self, e: usize, f: &mut FollowReferenceRt, dt: f64) {
        let reference = match &f.reference_name {
            Some(n) => self.entity_index(n),
            None => self.ghost.as_ref().filter(|g| g.owner == e).map(|g| g.entity),
        };
        let (Some(r), Some(mut car), Some(en)) = (reference.and_then(|r| self.entities.get(r)), f.vehicle, self.entities.get(e)) else { return };
        // ControllerFollowReference::Step measures from the entity's pose and speed, not from
        // the body's own: an action that changes the entity's speed under override (a speed
        // profile, which checks for none) steers and brakes the controller.
        let (x, y, h, v) = (en.x, en.y, en.h, en.speed);
        // Lateral error measured at the front axle when driving forward, positive to the
        // reference's right; and the longitudinal distance along our own heading, positive when
        // ahead of the reference. Both written as esmini's DistanceFromPointToLine2DWithAngle
        // computes them: on a tie the sign of zero (x·sin − y·cos gives +0) decides whether
        // atan2 of the cross-track term gives +π or −π when the speed term is negative.
        let (mx, my) = if v >= 0.0 { (x + f.wheelbase * h.cos(), y + f.wheelbase * h.sin()) } else { (x, y) };
        let to_line = |px: f64, py: f64, angle: f64| (px - r.x) * angle.sin() - (py - r.y) * angle.cos();
        let right = to_line(mx, my, r.h);
        let ahead = to_line(x, y, h + std::f64::consts::FRAC_PI_2);
        // GetAngleInIntervalMinusPIPlusPI, as ControllerFollowReference::Step wraps it: a
        // reference facing exactly the other way is +π (turn left), not −π.
        let dh = angle_pi(r.h - h);
        let ref_speed = if r.speed.abs() < SMALL {
            if r.speed < 0.0 {
                -SMALL
            } else {
                SMALL
            }
        } else {
            r.speed
        };
        let curvature = r.yaw_rate.clamp(-MAX_YAW_RATE, MAX_YAW_RATE) / ref_speed;
        let sign = if v < 0.0 { -1.0 } else { 1.0 };
        let steer =
            f.heading_gain * dh * sign + (f.cross_track_gain * right).atan2(f.speed_stabilizer + v) + f.curvature_gain * (curvature * f.wheelbase).atan();
        let damping = 2.0 * f.stiffness.sqrt();
        let acc = -f.stiffness * ahead - damping * (v - r.speed);
        car.drive_acc_steer(dt, acc, steer);
        if self.place_driven(e, &car) {
            f.vehicle = Some(car);
        }
    }
}

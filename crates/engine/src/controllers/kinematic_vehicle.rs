//! esmini's simple vehicle model, the body its driver models steer: a kinematic bicycle whose
//! velocity points `atan(0.15 · tan(wheel angle))` off the body axis (the reference point taken
//! 15 % of the length behind the steering centre), the heading turning at
//! `speed · sin(that angle) / (0.15 · length)`. Two ways to drive it: a target speed and a
//! heading to a target point (FollowGhostController), or an acceleration and a wheel angle
//! (FollowReferenceController). Reproduced from the behaviour of esmini 3.6's traces.

use std::f64::consts::PI;

/// Largest wheel angle, rad (60°).
const MAX_WHEEL_ANGLE: f64 = PI / 3.0;

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct KinematicVehicle {
    pub x: f64,
    pub y: f64,
    /// Heading in [0, 2π).
    pub h: f64,
    pub speed: f64,
    pub length: f64,
    pub max_speed: f64,
    pub wheel_angle: f64,
}

impl KinematicVehicle {
    pub(crate) fn new(x: f64, y: f64, h: f64, speed: f64, length: f64, max_speed: f64) -> KinematicVehicle {
        KinematicVehicle { x, y, h, speed, length: if length > 0.0 { length } else { 5.0 }, max_speed, wheel_angle: 0.0 }
    }

    /// Accelerate towards `target_speed` (gain and limit `max_acc`) and steer the heading error
    /// `heading_to_target`, the wheel angle limited more the faster it goes
    /// (`60° / (1 + steering_scale · speed²)`).
    pub(crate) fn drive_to_target(&mut self, dt: f64, target_speed: f64, heading_to_target: f64, max_acc: f64, steering_scale: f64) {
        let acc = (max_acc * (target_speed - self.speed)).clamp(-max_acc, max_acc);
        self.speed = (self.speed + acc * dt).clamp(-self.max_speed, self.max_speed);
        let limit = MAX_WHEEL_ANGLE / (1.0 + steering_scale * self.speed * self.speed);
        self.wheel_angle = heading_to_target.clamp(-limit, limit);
        self.advance(dt);
    }

    /// Apply an acceleration and a wheel angle (limited to 60°).
    pub(crate) fn drive_acc_steer(&mut self, dt: f64, acc: f64, wheel_angle: f64) {
        self.speed = (self.speed + acc * dt).clamp(-self.max_speed, self.max_speed);
        self.wheel_angle = wheel_angle.clamp(-MAX_WHEEL_ANGLE, MAX_WHEEL_ANGLE);
        self.advance(dt);
    }

    /// Move one step with the speed and wheel angle as they are (vehicle::Vehicle::Update).
    pub(crate) fn roll(&mut self, dt: f64) {
        self.advance(dt);
    }

    /// Whether the state is a real pose and speed.
    pub(crate) fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.h.is_finite() && self.speed.is_finite()
    }

    /// Move one step with the current speed and wheel angle.
    fn advance(&mut self, dt: f64) {
        let slip = (0.15 * self.wheel_angle.tan()).atan();
        let course = self.h + slip;
        let yaw_rate = self.speed * slip.sin() / (0.15 * self.length);
        let two_pi = 2.0 * PI;
        let mut h = (self.h + dt * yaw_rate) % two_pi;
        if h < 0.0 {
            h += two_pi;
        }
        self.h = h;
        self.x += dt * self.speed * course.cos();
        self.y += dt * self.speed * course.sin();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_wheels_drive_straight() {
        let mut v = KinematicVehicle::new(0.0, 0.0, 0.0, 10.0, 5.0, 70.0);
        for _ in 0..100 {
            v.drive_acc_steer(0.01, 0.0, 0.0);
        }
        assert!((v.x - 10.0).abs() < 1e-9 && v.y.abs() < 1e-12 && v.h == 0.0);
    }

    #[test]
    fn constant_wheel_angle_turns_on_a_circle() {
        // Yaw rate v·sin(β)/(0.15 L) with β = atan(0.15 tan δ): after time T the heading is
        // that rate times T.
        let (v0, len, delta) = (5.0, 4.0, 0.2_f64);
        let beta = (0.15 * delta.tan()).atan();
        let rate = v0 * beta.sin() / (0.15 * len);
        let mut v = KinematicVehicle::new(0.0, 0.0, 0.0, v0, len, 70.0);
        for _ in 0..100 {
            v.drive_acc_steer(0.01, 0.0, delta);
        }
        assert!((v.h - rate).abs() < 1e-9, "{} vs {}", v.h, rate);
    }

    #[test]
    fn target_speed_is_approached_at_the_limited_rate() {
        let mut v = KinematicVehicle::new(0.0, 0.0, 0.0, 0.0, 5.0, 100.0);
        v.drive_to_target(0.01, 20.0, 0.0, 10.0, 0.02);
        assert!((v.speed - 0.1).abs() < 1e-12);
    }
}

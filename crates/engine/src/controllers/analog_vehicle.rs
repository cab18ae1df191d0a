//! esmini's vehicle model driven by pedal and steering input (vehicle::Vehicle::
//! DrivingControlAnalog in esmini 3.6), as the looming controller and the UDP driver drive it:
//! the kinematic bicycle of `kinematic_vehicle`, accelerated by the throttle (negative: braking)
//! times its acceleration or deceleration limit, slowed by engine drag while the throttle
//! rests, held by a handbrake once braking has stopped it (until the pedal is released or
//! pressed again), and steered by a wheel angle that turns at `steering_rate · steering`,
//! less at speed, and returns towards straight ahead at 4 /s.

use super::kinematic_vehicle::KinematicVehicle;

/// esmini's SMALL_NUMBER: a throttle closer to zero than this rests.
const SMALL: f64 = 1e-6;
/// Speed lost per step while the throttle rests (ENGINE_BRAKE_FACTOR_DEFAULT).
const ENGINE_BRAKE: f64 = 0.001;
/// Rate at which the wheels return to straight ahead, 1/s (STEERING_RETURN_FACTOR_DEFAULT).
const STEERING_RETURN: f64 = 4.0;
/// Largest wheel angle at standstill, rad (STEERING_MAX_ANGLE, 60°).
const MAX_WHEEL_ANGLE: f64 = std::f64::consts::PI / 3.0;

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct AnalogVehicle {
    /// Pose, speed (limited to `car.max_speed`), length and wheel angle.
    pub car: KinematicVehicle,
    handbrake: bool,
    max_acc: f64,
    max_dec: f64,
    /// Wheel-angle rate per unit of steering input, 1/s.
    steering_rate: f64,
}

impl AnalogVehicle {
    pub(crate) fn new(car: KinematicVehicle, max_acc: f64, max_dec: f64, steering_rate: f64) -> AnalogVehicle {
        AnalogVehicle { car, handbrake: false, max_acc, max_dec, steering_rate }
    }

    /// One step of `dt`: `throttle` in −1..=1 (negative brakes), then `steering`, then the move.
    pub(crate) fn drive(&mut self, dt: f64, throttle: f64, steering: f64) {
        self.drive_speed(dt, throttle);
        let car = &mut self.car;
        let scale = 1.0 / (1.0 + 0.005 * car.speed * car.speed);
        let mut wheel = car.wheel_angle + scale * self.steering_rate * steering * dt;
        wheel *= 1.0 - STEERING_RETURN * dt;
        let limit = scale * MAX_WHEEL_ANGLE;
        car.wheel_angle = wheel.clamp(-limit, limit);
        car.roll(dt);
    }

    /// DrivingControlAnalog's throttle part.
    fn drive_speed(&mut self, dt: f64, throttle: f64) {
        let car = &mut self.car;
        let old = car.speed;
        if self.handbrake {
            // released (throttle at rest) or pressed: the handbrake lets go, the speed stays
            if throttle.abs() < SMALL || throttle > SMALL {
                self.handbrake = false;
            }
            return;
        }
        car.speed += if throttle < 0.0 { self.max_dec } else { self.max_acc } * throttle * dt;
        if old > 0.0 && car.speed < 0.0 {
            car.speed = 0.0;
            self.handbrake = true;
        } else {
            if throttle.abs() < SMALL {
                car.speed *= 1.0 - ENGINE_BRAKE;
            }
            car.speed = car.speed.clamp(-car.max_speed, car.max_speed);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn vehicle(speed: f64) -> AnalogVehicle {
        AnalogVehicle::new(KinematicVehicle::new(0.0, 0.0, 0.0, speed, 4.5, 30.0), 20.0, 20.0, 5.0)
    }

    #[test]
    fn full_throttle_accelerates_at_the_limit_up_to_the_top_speed() {
        let mut v = vehicle(0.0);
        v.drive(0.1, 1.0, 0.0);
        assert!((v.car.speed - 2.0).abs() < 1e-12);
        assert!((v.car.x - 0.2).abs() < 1e-12, "moves at the new speed: {}", v.car.x);
        for _ in 0..100 {
            v.drive(0.1, 1.0, 0.0);
        }
        assert_eq!(v.car.speed, 30.0);
    }

    #[test]
    fn braking_to_a_stop_holds_the_car_until_the_brake_is_released() {
        let mut v = vehicle(1.0);
        v.drive(0.1, -1.0, 0.0);
        assert_eq!(v.car.speed, 0.0);
        // still braking: held, no reversing
        v.drive(0.1, -1.0, 0.0);
        assert_eq!(v.car.speed, 0.0);
        // released: the handbrake lets go in this step; then the throttle acts
        v.drive(0.1, 0.0, 0.0);
        v.drive(0.1, 0.5, 0.0);
        assert!((v.car.speed - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_resting_throttle_drags_and_the_wheels_return() {
        let mut v = vehicle(10.0);
        v.drive(0.01, 0.0, 0.5);
        let steered = v.car.wheel_angle;
        // 5 /s · 0.5 · 0.01 s, scaled by 1 / (1 + 0.005 · v²), then returned by 4 %
        let expected = 0.025 / (1.0 + 0.005 * (10.0 * 0.999f64).powi(2)) * 0.96;
        assert!((steered - expected).abs() < 1e-12, "{steered} vs {expected}");
        assert!((v.car.speed - 9.99).abs() < 1e-12);
        v.drive(0.01, 0.0, 0.0);
        assert!(v.car.wheel_angle < steered && v.car.wheel_angle > 0.0);
        assert!(v.car.y > 0.0, "a positive wheel angle turns left");
    }
}

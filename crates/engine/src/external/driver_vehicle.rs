//! The vehicle an external entity's driver input drives: esmini's analog vehicle model
//! (`controllers/analog_vehicle.rs`) set up as ControllerUDPDriver::Activate sets it — the
//! entity's pose, speed and length, 20 m/s² to speed up and slow down, 30 m/s at most, the
//! wheels turning at 5 rad/s per unit of steering (vehicle.cpp's default).

use crate::controllers::analog_vehicle::AnalogVehicle;
use crate::controllers::kinematic_vehicle::KinematicVehicle;

const MAX_ACC: f64 = 20.0;
const MAX_DEC: f64 = 20.0;
const MAX_SPEED: f64 = 30.0;
const STEERING_RATE: f64 = 5.0;

pub(crate) fn udp_driver_vehicle(x: f64, y: f64, h: f64, speed: f64, length: f64) -> AnalogVehicle {
    AnalogVehicle::new(KinematicVehicle::new(x, y, h, speed, length, MAX_SPEED), MAX_ACC, MAX_DEC, STEERING_RATE)
}

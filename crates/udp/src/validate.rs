//! The checks a decoded message must pass before it drives anything: it is for the object the
//! port serves (esmini would steer whatever object the id names; osc2cr keeps each client to
//! its own entity), every number is finite, and its frame is not older than one already
//! accepted (`frame_order`). `accept` runs them all on a datagram.
//!
//! Driver input outside the ranges `ControllerUDPDriver.hpp` gives (pedals 0..=1, steering angle
//! −π/2..=π/2) is taken, as esmini takes it, not turned away: esmini's vehicle model is driven by
//! the one pedal `throttle − brake` (`Vehicle::DrivingControlAnalog`), so a negative throttle —
//! esmini's own `testUDPDriver-follow-trajectory.py` sends one — brakes. Such a message is
//! re-expressed as the pedals the engine takes, `throttle − brake` clamped to −1..=1 (esmini does
//! not clamp beyond that) and the steering angle to ±π/2, and counted (`clamp`).

use std::f64::consts::FRAC_PI_2;

use crate::frame_order::FrameOrder;
use crate::message::{decode, Body, Message};
use crate::rejection::Reason;

/// The values of `m`, for the object with esmini id `object_id`.
pub fn validate(m: &Message, object_id: u32) -> Result<(), Reason> {
    if m.header.object_id != object_id {
        return Err(Reason::ObjectId { got: m.header.object_id, expected: object_id });
    }
    for (field, value) in m.body.numbers() {
        if !value.is_finite() {
            return Err(Reason::NotFinite { field, value });
        }
    }
    Ok(())
}

/// Driver input with a pedal outside 0..=1 or a steering angle outside ±π/2 made one the engine
/// takes with esmini's effect (the pedal `throttle − brake`, clamped to −1..=1; the steering
/// clamped); whether it was. Other messages are left alone.
pub fn clamp(body: &mut Body) -> bool {
    let Body::DriverInput { throttle, brake, steering_angle } = *body else { return false };
    let in_range = (0.0..=1.0).contains(&throttle) && (0.0..=1.0).contains(&brake) && (-FRAC_PI_2..=FRAC_PI_2).contains(&steering_angle);
    if in_range {
        return false;
    }
    let pedal = (throttle - brake).clamp(-1.0, 1.0);
    *body = Body::DriverInput { throttle: pedal.max(0.0), brake: (-pedal).max(0.0), steering_angle: steering_angle.clamp(-FRAC_PI_2, FRAC_PI_2) };
    true
}

/// Datagram `bytes`, arrived on the port of object `object_id`, as a message that may drive it,
/// and whether its driver input was clamped; its frame becomes the newest accepted in `order`.
/// `Err` names the first thing wrong.
pub fn accept(bytes: &[u8], object_id: u32, order: &mut FrameOrder) -> Result<(Message, bool), Reason> {
    let mut m = decode(bytes)?;
    validate(&m, object_id)?;
    order.admit(m.header.frame_number)?;
    let clamped = clamp(&mut m.body);
    Ok((m, clamped))
}

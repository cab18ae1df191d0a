//! The checks a decoded message must pass before it drives anything: it is for the object the
//! port serves (esmini would steer whatever object the id names; osc2cr keeps each client to
//! its own entity), every number is finite, the pedals are within 0..=1 and the steering angle
//! within −π/2..=π/2 (the ranges `ControllerUDPDriver.hpp` gives), and its frame is not older
//! than one already accepted (`frame_order`). `accept` runs them all on a datagram.

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
    if let Body::DriverInput { throttle, brake, steering_angle } = m.body {
        for (field, value, min, max) in [("throttle", throttle, 0.0, 1.0), ("brake", brake, 0.0, 1.0), ("steeringAngle", steering_angle, -FRAC_PI_2, FRAC_PI_2)]
        {
            if !(min..=max).contains(&value) {
                return Err(Reason::OutOfRange { field, value, min, max });
            }
        }
    }
    Ok(())
}

/// Datagram `bytes`, arrived on the port of object `object_id`, as a message that may drive it;
/// its frame becomes the newest accepted in `order`. `Err` names the first thing wrong.
pub fn accept(bytes: &[u8], object_id: u32, order: &mut FrameOrder) -> Result<Message, Reason> {
    let m = decode(bytes)?;
    validate(&m, object_id)?;
    order.admit(m.header.frame_number)?;
    Ok(m)
}

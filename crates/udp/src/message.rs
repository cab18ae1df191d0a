//! The datagrams of esmini's UDP driver (message version 1, `ControllerUDPDriver.hpp`): a
//! header of four 32-bit unsigned integers — version, input mode, object id, frame number —
//! and then the fields of the input mode, 64-bit floats and, for the states, a one-byte
//! dead-reckoning flag. Everything is little-endian: esmini copies the bytes into its C structs
//! as they come, so it reads them in its host's order, which is little-endian on the x86 and ARM
//! machines it runs on; osc2cr reads little-endian on any host.
//!
//! A client sends either esmini's C structs raw — the header and the mode's struct, padded to a
//! multiple of 8 bytes, or the whole `DMMessage` union (88 bytes) whatever the mode — or the
//! fields packed one after the other as Python's `struct.pack` does with native alignment
//! (no padding after the header, none after the last byte). Each of these lengths is accepted.

use serde::Serialize;

pub use crate::input_mode::{InputMode, HEADER_SIZE, UNION_SIZE, VERSION};
use crate::rejection::Reason;

/// The header every message starts with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Header {
    pub version: u32,
    pub input_mode: u32,
    /// esmini's id of the object the message is for.
    pub object_id: u32,
    /// The client's count; esmini does not read it, osc2cr uses it to turn away stale messages.
    pub frame_number: u32,
}

/// The fields of a message, by input mode (esmini's `DMMSG…` structs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Body {
    DriverInput {
        /// 0..=1
        throttle: f64,
        /// 0..=1
        brake: f64,
        /// rad, −π/2..=π/2
        steering_angle: f64,
    },
    StateXyzhpr {
        x: f64,
        y: f64,
        z: f64,
        h: f64,
        p: f64,
        r: f64,
        speed: f64,
        wheel_angle: f64,
        dead_reckon: u8,
    },
    StateXyh {
        x: f64,
        y: f64,
        h: f64,
        speed: f64,
        wheel_angle: f64,
        dead_reckon: u8,
    },
    StateH {
        h: f64,
        speed: f64,
        wheel_angle: f64,
        dead_reckon: u8,
    },
}

impl Body {
    /// Every number of the body with its field name, in message order.
    pub fn numbers(&self) -> Vec<(&'static str, f64)> {
        match *self {
            Body::DriverInput { throttle, brake, steering_angle } => vec![("throttle", throttle), ("brake", brake), ("steeringAngle", steering_angle)],
            Body::StateXyzhpr { x, y, z, h, p, r, speed, wheel_angle, .. } => {
                vec![("x", x), ("y", y), ("z", z), ("h", h), ("p", p), ("r", r), ("speed", speed), ("wheelAngle", wheel_angle)]
            }
            Body::StateXyh { x, y, h, speed, wheel_angle, .. } => vec![("x", x), ("y", y), ("h", h), ("speed", speed), ("wheelAngle", wheel_angle)],
            Body::StateH { h, speed, wheel_angle, .. } => vec![("h", h), ("speed", speed), ("wheelAngle", wheel_angle)],
        }
    }
}

/// A datagram read as a message (its values not yet checked: `validate`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Message {
    pub header: Header,
    pub mode: InputMode,
    pub body: Body,
    /// Length of the datagram, bytes.
    pub size: usize,
}

/// Little-endian reader over a datagram whose length was checked.
struct Fields<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Fields<'_> {
    fn take<const N: usize>(&mut self) -> [u8; N] {
        let mut out = [0u8; N];
        if let Some(src) = self.bytes.get(self.at..self.at + N) {
            out.copy_from_slice(src);
        }
        self.at += N;
        out
    }
    fn u32(&mut self) -> u32 {
        u32::from_le_bytes(self.take())
    }
    fn f64(&mut self) -> f64 {
        f64::from_le_bytes(self.take())
    }
    fn u8(&mut self) -> u8 {
        self.take::<1>()[0]
    }
}

/// Reads datagram `bytes` as a message. `Err` when it cannot be one: shorter than the header,
/// a version other than 1 (checked first, as esmini does), an unknown input mode, or a length
/// that is none of the mode's (`InputMode::accepted_sizes`).
pub fn decode(bytes: &[u8]) -> Result<Message, Reason> {
    let size = bytes.len();
    if size < HEADER_SIZE {
        return Err(Reason::Short { size });
    }
    let mut f = Fields { bytes, at: 0 };
    let header = Header { version: f.u32(), input_mode: f.u32(), object_id: f.u32(), frame_number: f.u32() };
    if header.version != VERSION {
        return Err(Reason::Version { got: header.version });
    }
    let mode = InputMode::from_code(header.input_mode).ok_or(Reason::InputMode { got: header.input_mode })?;
    if !mode.accepted_sizes().contains(&size) {
        return Err(Reason::Length { mode, size });
    }
    let body = match mode {
        InputMode::DriverInput => Body::DriverInput { throttle: f.f64(), brake: f.f64(), steering_angle: f.f64() },
        InputMode::StateXyzhpr => Body::StateXyzhpr {
            x: f.f64(),
            y: f.f64(),
            z: f.f64(),
            h: f.f64(),
            p: f.f64(),
            r: f.f64(),
            speed: f.f64(),
            wheel_angle: f.f64(),
            dead_reckon: f.u8(),
        },
        InputMode::StateXyh => Body::StateXyh { x: f.f64(), y: f.f64(), h: f.f64(), speed: f.f64(), wheel_angle: f.f64(), dead_reckon: f.u8() },
        InputMode::StateH => Body::StateH { h: f.f64(), speed: f.f64(), wheel_angle: f.f64(), dead_reckon: f.u8() },
    };
    Ok(Message { header, mode, body, size })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_those_of_esminis_structs_and_of_struct_pack() {
        // struct.pack('iiiiddd'), 'iiiiddddddddB', 'iiiidddddB', 'iiiidddB'
        let packed: Vec<usize> = InputMode::ALL.iter().map(|m| m.packed_size()).collect();
        assert_eq!(packed, [40, 81, 57, 41]);
        // sizeof(DMHeader) + sizeof(DMMSG…)
        let structs: Vec<usize> = InputMode::ALL.iter().map(|m| m.struct_size()).collect();
        assert_eq!(structs, [40, 88, 64, 48]);
        assert_eq!(InputMode::StateXyh.accepted_sizes(), [57, 64, 88]);
        assert_eq!(InputMode::DriverInput.accepted_sizes(), [40, 88]);
    }

    #[test]
    fn a_union_sized_driver_message_reads_its_fields_and_ignores_the_rest() {
        let mut b = Vec::new();
        for v in [1u32, 1, 7, 42] {
            b.extend(v.to_le_bytes());
        }
        for v in [0.25f64, 0.5, -0.1] {
            b.extend(v.to_le_bytes());
        }
        b.resize(UNION_SIZE, 0xAB);
        let m = decode(&b).expect("decodes");
        assert_eq!(m.header, Header { version: 1, input_mode: 1, object_id: 7, frame_number: 42 });
        assert_eq!(m.body, Body::DriverInput { throttle: 0.25, brake: 0.5, steering_angle: -0.1 });
        assert_eq!(decode(&b[..39]), Err(Reason::Length { mode: InputMode::DriverInput, size: 39 }));
        assert_eq!(decode(&b[..15]), Err(Reason::Short { size: 15 }));
    }
}

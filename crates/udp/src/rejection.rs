//! Why a datagram is turned away, and how that is said: each reason names what was wrong and
//! what was expected, and a `Rejection` adds where (entity, port) and when (simulated time).
//! A rejected datagram counts as none: the entity goes on as it would without it.

use serde::Serialize;
use std::fmt;

use crate::input_mode::{InputMode, HEADER_SIZE, UNION_SIZE, VERSION};

/// What is wrong with a datagram.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum Reason {
    /// Shorter than the header.
    Short { size: usize },
    /// A message version other than 1.
    Version { got: u32 },
    /// An input mode that is not 1–4.
    InputMode { got: u32 },
    /// A length that is none of the mode's.
    Length { mode: InputMode, size: usize },
    /// The message is for another object than the one this port serves.
    ObjectId { got: u32, expected: u32 },
    /// A number that is NaN or infinite.
    NotFinite { field: &'static str, value: f64 },
    /// A frame number older than one already accepted for this object.
    OutOfOrder { frame: u32, newest: u32 },
    /// The socket failed to deliver (the text of the error).
    Receive { error: String },
}

impl fmt::Display for Reason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Reason::Short { size } => {
                write!(f, "a datagram of {size} bytes is shorter than the {HEADER_SIZE}-byte header (version, inputMode, objectId, frameNumber)")
            }
            Reason::Version { got } => write!(f, "message version {got}; only version {VERSION} is understood (esmini 3.6.0's UDP driver messages)"),
            Reason::InputMode { got } => write!(
                f,
                "unknown inputMode {got}; expected {}",
                InputMode::ALL.iter().map(|m| format!("{} {}", *m as u32, m.name())).collect::<Vec<_>>().join(", ")
            ),
            Reason::Length { mode, size } => {
                let sizes = mode.accepted_sizes();
                let list: Vec<String> = sizes
                    .iter()
                    .map(|s| match *s {
                        s if s == UNION_SIZE => format!("{s} (esmini's DMMessage)"),
                        s if s == mode.packed_size() && s == mode.struct_size() => format!("{s} (packed or C struct)"),
                        s if s == mode.packed_size() => format!("{s} (packed)"),
                        s => format!("{s} (C struct)"),
                    })
                    .collect();
                write!(f, "a {} message of {size} bytes; expected {}", mode.name(), list.join(", "))
            }
            Reason::ObjectId { got, expected } => write!(f, "objectId {got}, expected {expected}"),
            Reason::NotFinite { field, value } => write!(f, "{field} is {value}, not a finite number"),
            Reason::OutOfOrder { frame, newest } => write!(f, "frameNumber {frame} is older than frame {newest}, already accepted: out of order"),
            Reason::Receive { error } => write!(f, "the socket failed: {error}"),
        }
    }
}

/// A datagram turned away.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Rejection {
    /// The entity whose port it came to.
    pub entity: String,
    /// That entity's esmini object id.
    pub object_id: u32,
    pub port: u16,
    /// Simulated time of the step it would have driven, s (0: read with the Init frame).
    pub time: f64,
    pub reason: Reason,
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let why = match &self.reason {
            Reason::ObjectId { .. } => format!("{}: port {} serves `{}`, esmini object id {}", self.reason, self.port, self.entity, self.object_id),
            r => r.to_string(),
        };
        write!(f, "port {} (`{}`) at {:.3} s: datagram rejected: {why}", self.port, self.entity, self.time)
    }
}

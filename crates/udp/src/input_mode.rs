//! The wire layout of esmini's UDP driver messages (version 1): the message version, the
//! header's size, the input modes and the lengths a datagram of each mode may have. The decoder
//! (`message.rs`) and its rejections (`rejection.rs`) both read it.

use serde::Serialize;

/// The only message version esmini 3.6.0 understands (`UDP_DRIVER_MESSAGE_VERSION`).
pub const VERSION: u32 = 1;
/// Bytes of the header: version, input mode, object id, frame number.
pub const HEADER_SIZE: usize = 16;
/// Bytes of esmini's whole message (`sizeof(DMMessage)`: the header and a union of the mode
/// structs, the largest being the 65-byte XYZHPR state padded to 72).
pub const UNION_SIZE: usize = 88;

/// What a message gives: driver input, or a state of one of three kinds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum InputMode {
    /// Throttle, brake and steering for esmini's vehicle model.
    DriverInput = 1,
    /// x, y, z, heading, pitch, roll, speed, wheel angle: placed as given, off the road if so.
    StateXyzhpr = 2,
    /// x, y, heading, speed, wheel angle: placed on the road surface.
    StateXyh = 3,
    /// heading, speed, wheel angle: turned where it is.
    StateH = 4,
}

impl InputMode {
    pub const ALL: [InputMode; 4] = [InputMode::DriverInput, InputMode::StateXyzhpr, InputMode::StateXyh, InputMode::StateH];

    /// The mode of header code `code` (esmini's `InputMode`; 0, "no input", is not a message).
    pub fn from_code(code: u32) -> Option<InputMode> {
        InputMode::ALL.into_iter().find(|m| *m as u32 == code)
    }

    /// The name esmini's Python clients give the mode (`udp_osi_common.py`).
    pub fn name(self) -> &'static str {
        match self {
            InputMode::DriverInput => "driverInput",
            InputMode::StateXyzhpr => "stateXYZHPR",
            InputMode::StateXyh => "stateXYH",
            InputMode::StateH => "stateH",
        }
    }

    /// Doubles in the mode's fields, and whether a dead-reckoning byte follows them.
    fn fields(self) -> (usize, bool) {
        match self {
            InputMode::DriverInput => (3, false),
            InputMode::StateXyzhpr => (8, true),
            InputMode::StateXyh => (5, true),
            InputMode::StateH => (3, true),
        }
    }

    /// The header and the fields packed without padding (Python's `struct.pack`).
    pub fn packed_size(self) -> usize {
        let (doubles, flag) = self.fields();
        HEADER_SIZE + 8 * doubles + usize::from(flag)
    }

    /// The header and the mode's C struct, padded to its 8-byte alignment.
    pub fn struct_size(self) -> usize {
        self.packed_size().div_ceil(8) * 8
    }

    /// Every length a datagram of this mode may have, shortest first.
    pub fn accepted_sizes(self) -> Vec<usize> {
        let mut sizes = vec![self.packed_size(), self.struct_size(), UNION_SIZE];
        sizes.dedup();
        sizes
    }
}

//! What a server tells while it runs, as it happens: a port opened (`Listening`), a datagram
//! turned away, a frame run, the frame's OSI message. The server loop (`serve`) and the OSI
//! output (`osi_out`) both tell an `Observer`; a command line prints what it is told.

use std::net::SocketAddr;

use crate::controller_properties::ExecMode;
use crate::rejection::Rejection;

/// A port opened for an entity.
#[derive(Debug, Clone, PartialEq)]
pub struct Listening {
    pub entity: String,
    pub object_id: u32,
    pub address: SocketAddr,
    pub exec: ExecMode,
    /// Opened with the Init frame, which reads its first datagram before the first step (as
    /// esmini's controller step at time 0 does); otherwise the next step reads it first.
    pub at_init: bool,
}

/// What a server tells while it runs (a command line prints it; the default says nothing).
pub trait Observer {
    /// A port is open: datagrams for `l.entity` are read from now on.
    fn listening(&mut self, _l: &Listening) {}
    /// A datagram was turned away.
    fn rejected(&mut self, _r: &Rejection) {}
    /// A frame was run (the Init frame too, once its ports were read); `time` is the
    /// simulated time it reached. The next step reads the ports next.
    fn stepped(&mut self, _time: f64) {}
    /// The OSI GroundTruth message of the frame just run (when `ServeOptions::osi`).
    fn osi_frame(&mut self, _message: &[u8]) {}
}

/// An observer that is told nothing.
pub struct Silent;
impl Observer for Silent {}

//! What arrives on one port in one step, as esmini's `ControllerUDPDriver::Step` reads it. In
//! asynchronous mode every datagram queued is read, nothing is waited for, and the newest good
//! one is the step's message (the others are superseded). In synchronous mode one datagram is
//! read, waiting for it up to esmini's 500 ms; if none comes, or the one that comes is turned
//! away, the step goes on without a message. Each datagram is checked (`validate::accept`)
//! in the order it arrived, so a stale frame is caught even among several queued at once.

use std::io::ErrorKind;
use std::net::{SocketAddr, UdpSocket};
use std::time::Duration;

use crate::controller_properties::ExecMode;
use crate::frame_order::FrameOrder;
use crate::message::Message;
use crate::rejection::Reason;
use crate::validate::accept;

/// esmini's wait for a datagram in synchronous mode (`UDP_SYNCHRONOUS_MODE_TIMEOUT_MS`).
pub const SYNCHRONOUS_TIMEOUT: Duration = Duration::from_millis(500);
/// Most datagrams read from one port in one step (a flood is read on in the next).
const MAX_PER_STEP: usize = 4096;
/// Receive buffer: longer than any message, so that a long datagram is seen as too long.
const BUFFER: usize = 2048;

/// A bound port and how it is read.
#[derive(Debug)]
pub struct Endpoint {
    socket: UdpSocket,
    pub exec: ExecMode,
    pub address: SocketAddr,
    timeout: Duration,
}

/// What one step read from a port.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Arrival {
    /// The step's message, if a good one came.
    pub message: Option<Message>,
    /// Good datagrams a newer one replaced (asynchronous mode).
    pub superseded: usize,
    /// Datagrams turned away, in arrival order.
    pub rejected: Vec<Reason>,
    /// Datagrams read.
    pub datagrams: usize,
    /// Good messages whose driver input was clamped (`validate::clamp`).
    pub clamped: usize,
}

impl Endpoint {
    /// Binds `address` for `exec`; `timeout` is how long synchronous mode waits.
    pub fn bind(address: SocketAddr, exec: ExecMode, timeout: Duration) -> std::io::Result<Endpoint> {
        let socket = UdpSocket::bind(address)?;
        match exec {
            ExecMode::Asynchronous => socket.set_nonblocking(true)?,
            ExecMode::Synchronous => socket.set_read_timeout(Some(timeout.max(Duration::from_millis(1))))?,
        }
        let address = socket.local_addr()?;
        Ok(Endpoint { socket, exec, address, timeout })
    }

    /// Reads the step's datagrams for the object with esmini id `object_id`.
    pub fn receive(&self, object_id: u32, order: &mut FrameOrder) -> Arrival {
        let mut arrival = Arrival::default();
        let mut buffer = [0u8; BUFFER];
        let reads = match self.exec {
            ExecMode::Asynchronous => MAX_PER_STEP,
            ExecMode::Synchronous => 1,
        };
        let mut interrupted = 0;
        while arrival.datagrams < reads {
            match self.socket.recv(&mut buffer) {
                Ok(n) => {
                    arrival.datagrams += 1;
                    match accept(buffer.get(..n).unwrap_or(&buffer), object_id, order) {
                        Ok((m, clamped)) => {
                            arrival.clamped += usize::from(clamped);
                            if arrival.message.replace(m).is_some() {
                                arrival.superseded += 1;
                            }
                        }
                        Err(reason) => arrival.rejected.push(reason),
                    }
                }
                // nothing (more) queued, or the synchronous wait is over
                Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => break,
                Err(e) if e.kind() == ErrorKind::Interrupted && interrupted < 10 => interrupted += 1,
                Err(e) => {
                    // e.g. an ICMP error queued on the socket: reported, and the step goes on
                    arrival.rejected.push(Reason::Receive { error: e.to_string() });
                    break;
                }
            }
        }
        arrival
    }

    /// The synchronous wait.
    pub fn timeout(&self) -> Duration {
        self.timeout
    }
}

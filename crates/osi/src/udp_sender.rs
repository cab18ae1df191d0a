//! Sending messages over UDP as esmini's `OSIReporter` sends them (`--osi_receiver_ip`), so that
//! esmini's clients (`udp_osi_common.py`'s `OSIReceiver`) read them unchanged: each message is
//! cut into parts of at most 8,192 bytes, each sent as one datagram of a 32-bit signed counter
//! (1, 2, 3, …; the last part's negated), a 32-bit unsigned length of the part, and the part,
//! little-endian (esmini's struct, as its hosts lay it out). An empty message sends nothing,
//! as in esmini.

use std::net::{SocketAddr, ToSocketAddrs, UdpSocket};

/// The port esmini sends to (`OSI_OUT_PORT`).
pub const OSI_PORT: u16 = 48198;
/// Largest part of a message in one datagram (`OSI_MAX_UDP_DATA_SIZE`).
pub const MAX_PART: usize = 8192;

/// The datagrams of one message.
pub fn datagrams(message: &[u8]) -> Vec<Vec<u8>> {
    let parts: Vec<&[u8]> = message.chunks(MAX_PART).collect();
    let n = parts.len();
    parts
        .into_iter()
        .enumerate()
        .map(|(i, part)| {
            let counter = (i + 1) as i32;
            let counter = if i + 1 == n { -counter } else { counter };
            let mut d = Vec::with_capacity(8 + part.len());
            d.extend_from_slice(&counter.to_le_bytes());
            d.extend_from_slice(&(part.len() as u32).to_le_bytes());
            d.extend_from_slice(part);
            d
        })
        .collect()
}

/// A socket that sends every message to one receiver.
#[derive(Debug)]
pub struct Sender {
    socket: UdpSocket,
    pub receiver: SocketAddr,
    /// Datagrams the network refused (the sending goes on).
    pub failed: usize,
}

/// `HOST[:PORT]` as an address (the port defaults to esmini's 48198).
pub fn receiver_address(spec: &str) -> Result<SocketAddr, String> {
    let with_port = if spec.parse::<SocketAddr>().is_ok() || spec.rsplit_once(':').is_some_and(|(h, p)| !h.contains(':') && p.parse::<u16>().is_ok()) {
        spec.to_string()
    } else if spec.contains(':') && !spec.starts_with('[') {
        format!("[{spec}]:{OSI_PORT}")
    } else {
        format!("{spec}:{OSI_PORT}")
    };
    with_port.to_socket_addrs().map_err(|e| format!("OSI receiver `{spec}`: {e}"))?.next().ok_or_else(|| format!("OSI receiver `{spec}`: no address"))
}

impl Sender {
    /// A sender to `receiver`.
    pub fn new(receiver: SocketAddr) -> std::io::Result<Sender> {
        let local: SocketAddr = if receiver.is_ipv4() { "0.0.0.0:0" } else { "[::]:0" }.parse().map_err(std::io::Error::other)?;
        let socket = UdpSocket::bind(local)?;
        Ok(Sender { socket, receiver, failed: 0 })
    }

    /// Sends one message; a part that cannot be sent ends this message's sending (as esmini
    /// gives up) and is counted.
    pub fn send(&mut self, message: &[u8]) {
        for d in datagrams(message) {
            if !matches!(self.socket.send_to(&d, self.receiver), Ok(n) if n == d.len()) {
                self.failed += 1;
                return;
            }
        }
    }
}

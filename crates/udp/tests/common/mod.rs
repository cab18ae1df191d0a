//! Test support: a UDP client written from esmini's description of its UDP driver messages
//! (`ControllerUDPDriver.hpp`: a header of four little-endian u32 — version, inputMode,
//! objectId, frameNumber — then f64 fields and, for states, a dead-reckoning byte; packed as
//! Python's `struct.pack` packs them), an observer that plays a script of datagrams in
//! lockstep with the server (frame k's datagrams are sent just before frame k reads its port;
//! frame 0 is the Init frame), free ports, and the fixtures.

#![allow(dead_code)]

use std::collections::BTreeMap;
use std::net::UdpSocket;
use std::path::{Path, PathBuf};

use udp::{Listening, Observer, Pace, Rejection, ServeOptions};

pub(crate) fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures").join(name)
}

/// Serve options: these scenario parameters, as fast as the datagrams come; the run ends at
/// the time cap `duration` (the scenarios' stop trigger is left far behind: in the frame it
/// fires a synchronous port is read for nothing, as the engine learns only then that it fired).
pub(crate) fn options(params: &[(&str, String)], duration: f64) -> ServeOptions {
    let mut o = ServeOptions { pace: Some(Pace::AsFastAsPossible), ..ServeOptions::default() };
    o.convert.max_time = duration;
    o.convert.parameters = params.iter().map(|(n, v)| (n.to_string(), v.clone())).collect();
    o.convert.parameters.push(("Duration".into(), "1000".into()));
    o
}

/// A UDP port free on 127.0.0.1 now.
pub(crate) fn free_port() -> u16 {
    UdpSocket::bind("127.0.0.1:0").and_then(|s| s.local_addr()).expect("a free port").port()
}

/// Two consecutive free ports, the first returned.
pub(crate) fn free_port_pair() -> u16 {
    loop {
        let a = UdpSocket::bind("127.0.0.1:0").expect("a free port");
        let p = a.local_addr().expect("address").port();
        if p < u16::MAX && UdpSocket::bind(("127.0.0.1", p + 1)).is_ok() {
            return p;
        }
    }
}

// ---- the messages, from the protocol description ----

fn header(mode: u32, object_id: u32, frame: u32) -> Vec<u8> {
    [1u32, mode, object_id, frame].iter().flat_map(|v| v.to_le_bytes()).collect()
}

fn with(mut b: Vec<u8>, doubles: &[f64], flag: Option<u8>) -> Vec<u8> {
    for d in doubles {
        b.extend(d.to_le_bytes());
    }
    b.extend(flag);
    b
}

/// driverInput (mode 1): throttle, brake, steering angle.
pub(crate) fn driver(object_id: u32, frame: u32, throttle: f64, brake: f64, steering: f64) -> Vec<u8> {
    with(header(1, object_id, frame), &[throttle, brake, steering], None)
}

/// stateXYZHPR (mode 2): x, y, z, h, p, r, speed, wheel angle, dead reckoning.
pub(crate) fn xyzhpr(object_id: u32, frame: u32, v: [f64; 8], dead_reckon: u8) -> Vec<u8> {
    with(header(2, object_id, frame), &v, Some(dead_reckon))
}

/// stateXYH (mode 3): x, y, h, speed, wheel angle, dead reckoning.
pub(crate) fn xyh(object_id: u32, frame: u32, x: f64, y: f64, h: f64, speed: f64, dead_reckon: u8) -> Vec<u8> {
    with(header(3, object_id, frame), &[x, y, h, speed, 0.0], Some(dead_reckon))
}

/// stateH (mode 4): h, speed, wheel angle, dead reckoning.
pub(crate) fn state_h(object_id: u32, frame: u32, h: f64, speed: f64, dead_reckon: u8) -> Vec<u8> {
    with(header(4, object_id, frame), &[h, speed, 0.0], Some(dead_reckon))
}

/// `b` padded with zeros to `n` bytes (a C struct, or esmini's whole 88-byte DMMessage).
pub(crate) fn padded(mut b: Vec<u8>, n: usize) -> Vec<u8> {
    b.resize(n, 0);
    b
}

/// `b` with its 4-byte header field `k` (0 version, 1 inputMode, 2 objectId, 3 frameNumber) set.
pub(crate) fn with_header_field(mut b: Vec<u8>, k: usize, v: u32) -> Vec<u8> {
    b[4 * k..4 * k + 4].copy_from_slice(&v.to_le_bytes());
    b
}

// ---- the client in lockstep ----

/// Plays, for each port, a script of frames: the datagrams of frame k are sent just before the
/// server reads the port for frame k (frame 0 when the port opens with the Init frame, else
/// after the step that opened it). Records what it is told.
pub(crate) struct Lockstep {
    client: UdpSocket,
    scripts: BTreeMap<String, Vec<Vec<Vec<u8>>>>,
    cursor: BTreeMap<String, (u16, usize)>,
    pub listening: Vec<Listening>,
    /// Frames run (the Init frame included) when each port opened.
    pub opened_after: Vec<usize>,
    pub rejections: Vec<Rejection>,
    pub steps: usize,
}

impl Lockstep {
    /// Scripts by entity name: `frames[k]` are the datagrams of frame k.
    pub(crate) fn new(scripts: Vec<(&str, Vec<Vec<Vec<u8>>>)>) -> Lockstep {
        Lockstep {
            client: UdpSocket::bind("127.0.0.1:0").expect("client socket"),
            scripts: scripts.into_iter().map(|(n, s)| (n.to_string(), s)).collect(),
            cursor: BTreeMap::new(),
            listening: Vec::new(),
            opened_after: Vec::new(),
            rejections: Vec::new(),
            steps: 0,
        }
    }

    /// One datagram per frame for `entity`.
    pub(crate) fn one_each(entity: &str, frames: Vec<Vec<u8>>) -> Lockstep {
        Lockstep::new(vec![(entity, frames.into_iter().map(|d| vec![d]).collect())])
    }

    /// The frames scripted for `entity`.
    pub(crate) fn script(&self, entity: &str) -> Vec<Vec<Vec<u8>>> {
        self.scripts.get(entity).cloned().unwrap_or_default()
    }

    fn send_next(&mut self, entity: &str) {
        let Some((port, k)) = self.cursor.get_mut(entity) else { return };
        if let Some(frame) = self.scripts.get(entity).and_then(|s| s.get(*k)) {
            for d in frame {
                self.client.send_to(d, ("127.0.0.1", *port)).expect("sent");
            }
        }
        *k += 1;
    }
}

impl Observer for Lockstep {
    fn listening(&mut self, l: &Listening) {
        self.listening.push(l.clone());
        self.opened_after.push(self.steps);
        self.cursor.insert(l.entity.clone(), (l.address.port(), 0));
        if l.at_init {
            self.send_next(&l.entity.clone());
        }
    }
    fn rejected(&mut self, r: &Rejection) {
        self.rejections.push(r.clone());
    }
    fn stepped(&mut self, _time: f64) {
        self.steps += 1;
        let names: Vec<String> = self.cursor.keys().cloned().collect();
        for n in names {
            self.send_next(&n);
        }
    }
}

/// The state of `entity` at time `t` in a served run.
pub(crate) fn at(outcome: &udp::Outcome, entity: &str, t: f64) -> engine::Sample {
    let e = outcome.entity(entity).unwrap_or_else(|| panic!("{entity} was not served"));
    e.states.iter().find(|(time, _)| (time - t).abs() < 1e-9).map(|(_, s)| *s).unwrap_or_else(|| panic!("no state of {entity} at {t}"))
}

pub(crate) fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

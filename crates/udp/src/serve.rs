//! The server loop: a scenario run one step at a time in a `convert::ClosedLoop` whose outside
//! drivers are the entities of controllers that need one (`engine::External::controllers`).
//! An entity with a UDPDriverController gets its port when its controller is activated (as
//! esmini's `Activate` opens it; one activated by the Init has its first datagram read with the
//! Init frame, as esmini's controller step of that frame reads it), and from then on each step
//! reads its port (`receive`) and turns what came into the engine's input (`translate`).
//! Other outside drivers (External, Interactive, ExternalDriverModel) are held where they are,
//! with a note. At the end the run is converted as `osc2cr convert` converts the file.

use std::collections::BTreeMap;
use std::fmt;
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

use convert::{ClosedLoop, ConvertOptions, Failure};
use engine::{External, Input, Source};
use openscenario::Controller;

use crate::controller_properties::{base_port, is_udp_driver, port, read_properties, udp_drivers, ExecMode};
use crate::frame_order::FrameOrder;
use crate::object_ids::{object_id, object_ids};
use crate::observer::{Listening, Observer};
use crate::osi_out::OsiOut;
use crate::outcome::{EntityReport, Outcome, MAX_KEPT_REJECTIONS};
use crate::pacing::{Clock, Pace};
use crate::receive::{Arrival, Endpoint, SYNCHRONOUS_TIMEOUT};
use crate::rejection::Rejection;
use crate::translate::Driving;

/// How to serve a scenario.
#[derive(Debug, Clone)]
pub struct ServeOptions {
    /// The conversion's options (step, time cap, ego, parameters, …).
    pub convert: ConvertOptions,
    /// The address the ports are bound on (default 127.0.0.1: this machine only).
    pub bind: IpAddr,
    /// Replaces the scenario's base port (`basePort`, else 49950).
    pub base_port: Option<u16>,
    /// `None`: real time when a port is asynchronous, else as fast as possible.
    pub pace: Option<Pace>,
    /// How long a synchronous port waits for its datagram each step (esmini: 500 ms).
    pub synchronous_timeout: Duration,
    /// Compose an OSI GroundTruth message per frame (told to `Observer::osi_frame`).
    pub osi: bool,
    /// Send each message there too, as esmini's `--osi_receiver_ip` sends it.
    pub osi_receiver: Option<SocketAddr>,
    /// Set from elsewhere (Ctrl-C) to end the run after the current step; the run so far is
    /// converted and the outcome says it was interrupted.
    pub stop: Option<Arc<AtomicBool>>,
}

impl Default for ServeOptions {
    fn default() -> Self {
        ServeOptions {
            convert: ConvertOptions::default(),
            bind: IpAddr::V4(Ipv4Addr::LOCALHOST),
            base_port: None,
            pace: None,
            synchronous_timeout: SYNCHRONOUS_TIMEOUT,
            osi: false,
            osi_receiver: None,
            stop: None,
        }
    }
}

/// Why a scenario could not be served.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// Loading the scenario, its map, or the first frame failed.
    Start(Failure),
    /// A UDPDriverController's properties are wrong (esmini stops on them too).
    Setup(String),
    /// A port could not be opened.
    Bind(String),
    /// A step failed.
    Step(Failure),
    /// The OSI receiver could not be reached.
    Osi(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Start(e) | Error::Step(e) => write!(f, "{:?} stage: {}", e.stage, e.message),
            Error::Setup(m) | Error::Bind(m) | Error::Osi(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Error {}

/// One entity served over UDP.
struct Link {
    controller: Controller,
    endpoint: Option<Endpoint>,
    driving: Driving,
    order: FrameOrder,
    report: EntityReport,
}

/// The run's serving state.
struct Server<'o> {
    options: &'o ServeOptions,
    observer: &'o mut dyn Observer,
    ids: Vec<(String, u32)>,
    base: u16,
    links: BTreeMap<usize, Link>,
    /// Outside drivers not served over UDP, told once.
    unserved: Vec<usize>,
    notes: Vec<String>,
    rejections: Vec<Rejection>,
    rejections_not_kept: usize,
}

/// Runs the scenario file `path`, serving its UDP drivers, to its end (its stop trigger or the
/// time cap); the observer is told of ports, rejections and steps as they happen.
pub fn serve(path: &Path, options: &ServeOptions, observer: &mut dyn Observer) -> Result<Outcome, Error> {
    let mut session = ClosedLoop::start(path, &options.convert, &External::controllers()).map_err(Error::Start)?;
    let mut notes = Vec::new();
    let base = base_port(session.scenario(), options.base_port, &mut notes).map_err(Error::Setup)?;
    let any_asynchronous = udp_drivers(session.scenario()).iter().any(|c| read_properties(c, &mut Vec::new()).is_ok_and(|p| p.exec == ExecMode::Asynchronous));
    let pace = options.pace.unwrap_or(if any_asynchronous { Pace::RealTime(1.0) } else { Pace::AsFastAsPossible });
    let ids = object_ids(session.scenario());
    let mut server =
        Server { options, observer, ids, base, links: BTreeMap::new(), unserved: Vec::new(), notes, rejections: Vec::new(), rejections_not_kept: 0 };
    let dt = options.convert.step;
    let mut osi = match options.osi || options.osi_receiver.is_some() {
        true => Some(OsiOut::new(&session, options.osi_receiver).map_err(|e| Error::Osi(format!("cannot send OSI messages: {e}")))?),
        false => None,
    };
    let stopped = || options.stop.as_ref().is_some_and(|s| s.load(Ordering::SeqCst));

    // the Init frame: ports of controllers it activated open, and their first datagram is read
    server.follow_activations(&session, true)?;
    for (&index, link) in server.links.iter_mut() {
        let Some(endpoint) = &link.endpoint else { continue };
        let arrival = endpoint.receive(link.report.object_id, &mut link.order);
        let message = tally(link, &arrival, 0.0, &mut server.rejections, &mut server.rejections_not_kept, server.observer);
        if let Some(m) = message {
            link.driving.read_without_step(m.body);
        }
        if let Some(s) = session.state(index) {
            link.report.states.push((session.time(), s));
        }
    }
    server.observer.stepped(session.time());
    if let Some(o) = &mut osi {
        o.frame(&session, server.observer);
    }

    let clock = Clock::start(pace);
    let t0 = session.time();
    let mut interrupted = false;
    while !session.is_over() {
        if stopped() {
            interrupted = true;
            break;
        }
        let t = session.time() + dt;
        clock.wait_until(t - t0);
        let (inputs, without_message) = server.inputs(&session, t, dt);
        let before = session.time();
        session.step_with(&inputs).map_err(Error::Step)?;
        // the frame in which the stop trigger fires records nothing: it was no step
        if session.time() > before {
            for index in without_message {
                if let Some(link) = server.links.get_mut(&index) {
                    link.report.steps_without_message += 1;
                }
            }
        }
        server.follow_activations(&session, false)?;
        for (&index, link) in server.links.iter_mut() {
            if let (Some(s), true) = (session.state(index), link.endpoint.is_some()) {
                link.report.states.push((session.time(), s));
            }
        }
        server.observer.stepped(session.time());
        if let (Some(o), true) = (&mut osi, session.time() > before) {
            o.frame(&session, server.observer);
        }
    }
    if let Some(o) = &osi {
        server.notes.extend(o.notes());
    }

    let (conversion, _) = session.finish();
    let steps = ((session.time() - t0) / dt).round().max(0.0) as usize;
    Ok(Outcome {
        scenario: path.to_path_buf(),
        output_name: convert::output_file_name(path, None),
        steps,
        time: session.time(),
        pace: match pace {
            Pace::RealTime(f) => format!("real time ×{f}"),
            Pace::AsFastAsPossible => "as fast as possible".into(),
        },
        entities: server.links.into_values().map(|l| l.report).collect(),
        rejections: server.rejections,
        rejections_not_kept: server.rejections_not_kept,
        notes: server.notes,
        interrupted,
        osi_frames: osi.as_ref().map_or(0, |o| o.frames),
        warnings: conversion.warnings.clone(),
        failure: conversion.result.as_ref().err().cloned(),
        conversion,
    })
}

/// Counts what `arrival` brought to `link` at time `time`, records and tells its rejections;
/// the step's message.
fn tally(
    link: &mut Link,
    arrival: &Arrival,
    time: f64,
    kept: &mut Vec<Rejection>,
    not_kept: &mut usize,
    observer: &mut dyn Observer,
) -> Option<crate::message::Message> {
    let r = &mut link.report;
    r.datagrams += arrival.datagrams;
    r.superseded += arrival.superseded;
    r.rejected += arrival.rejected.len();
    r.accepted += usize::from(arrival.message.is_some());
    r.clamped += arrival.clamped;
    for reason in &arrival.rejected {
        let port = link.endpoint.as_ref().map_or(0, |e| e.address.port());
        let rejection = Rejection { entity: r.name.clone(), object_id: r.object_id, port, time, reason: reason.clone() };
        observer.rejected(&rejection);
        if kept.len() < MAX_KEPT_REJECTIONS {
            kept.push(rejection);
        } else {
            *not_kept += 1;
        }
    }
    arrival.message
}

impl Server<'_> {
    /// Links the entities whose controller is a UDP driver, and opens the port of each whose
    /// controller is active (again with its port if a new controller was assigned).
    fn follow_activations(&mut self, session: &ClosedLoop, at_init: bool) -> Result<(), Error> {
        for ext in session.external() {
            let Source::Controller(c) = &ext.source else { continue };
            if !is_udp_driver(c) {
                if ext.active && !self.unserved.contains(&ext.index) {
                    self.unserved.push(ext.index);
                    self.notes.push(format!(
                        "`{}` has a {} controller, which is not served over UDP: it is held where it is",
                        ext.name,
                        c.properties.get("esminiController").unwrap_or(&c.name)
                    ));
                }
                continue;
            }
            // (its notes were taken when the base port was read from every UDP driver)
            let props = read_properties(c, &mut Vec::new()).map_err(Error::Setup)?;
            let object_id = object_id(&self.ids, &ext.name).ok_or_else(|| Error::Setup(format!("`{}` has no esmini object id", ext.name)))?;
            let link = self.links.entry(ext.index).or_insert_with(|| Link {
                controller: c.clone(),
                endpoint: None,
                driving: Driving::new(),
                order: FrameOrder::default(),
                report: EntityReport {
                    name: ext.name.clone(),
                    object_id,
                    address: None,
                    exec: props.exec,
                    datagrams: 0,
                    accepted: 0,
                    superseded: 0,
                    rejected: 0,
                    clamped: 0,
                    steps_without_message: 0,
                    states: Vec::new(),
                },
            });
            if link.controller != *c {
                // another controller instance: esmini starts it afresh
                link.controller = c.clone();
                link.driving = Driving::new();
                link.order = FrameOrder::default();
                link.report.exec = props.exec;
            }
            if !ext.active {
                continue;
            }
            let port = port(&props, self.base, object_id).map_err(|m| Error::Setup(format!("`{}`: {m}", ext.name)))?;
            let address = SocketAddr::new(self.options.bind, port);
            if link.endpoint.as_ref().is_some_and(|e| e.address == address && e.exec == props.exec) {
                continue;
            }
            // the old port closes before the new one opens (it may be the same number)
            link.endpoint = None;
            let endpoint = Endpoint::bind(address, props.exec, self.options.synchronous_timeout)
                .map_err(|e| Error::Bind(format!("cannot listen on {address} for `{}`: {e}", ext.name)))?;
            let listening = Listening { entity: ext.name.clone(), object_id, address: endpoint.address, exec: props.exec, at_init };
            link.report.address = Some(endpoint.address.to_string());
            link.endpoint = Some(endpoint);
            self.observer.listening(&listening);
        }
        Ok(())
    }

    /// The inputs of the step that ends at time `t`: what each active UDP driver's port
    /// brought, a hold for outside drivers not served; for a UDP driver still waiting for its
    /// controller, the input it gets if the controller is activated in this step (esmini's
    /// controller steps once without a message then).
    /// Also the entities whose port brought no message.
    fn inputs(&mut self, session: &ClosedLoop, t: f64, dt: f64) -> (Vec<(usize, Input)>, Vec<usize>) {
        let mut inputs = Vec::new();
        let mut without_message = Vec::new();
        for ext in session.external() {
            let now = session.state(ext.index);
            let Some(link) = self.links.get_mut(&ext.index) else {
                if ext.active {
                    inputs.push((ext.index, Input::Hold));
                }
                continue;
            };
            match (&link.endpoint, ext.active) {
                (Some(endpoint), true) => {
                    let arrival = endpoint.receive(link.report.object_id, &mut link.order);
                    let message = tally(link, &arrival, t, &mut self.rejections, &mut self.rejections_not_kept, self.observer);
                    if message.is_none() {
                        without_message.push(ext.index);
                    }
                    inputs.push((ext.index, link.driving.input(message.map(|m| m.body), now.as_ref(), dt)));
                }
                (_, false) => {
                    if now.is_some() {
                        inputs.push((ext.index, link.driving.clone().input(None, now.as_ref(), dt)));
                    }
                }
                (None, true) => inputs.push((ext.index, Input::Hold)),
            }
        }
        (inputs, without_message)
    }
}

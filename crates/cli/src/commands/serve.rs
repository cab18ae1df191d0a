//! `osc2cr serve SCENARIO --udp -o OUT_DIR`: runs a scenario whose UDPDriverController entities
//! are driven over UDP by clients written for esmini, then writes the run as CommonRoad as
//! `osc2cr convert` writes the file. All the work is `udp::serve`; this maps options, tells
//! what happens on stderr, prints a summary and writes the file.

use std::net::IpAddr;
use std::path::PathBuf;

use convert::{ConvertOptions, EgoChoice, Stage};
use udp::{Listening, Observer, Pace, Rejection, ServeOptions};

use crate::failure::Failure;
use crate::shared_options::{CommonRoadArgs, RunArgs};

pub(crate) const ABOUT: &str = "\
Run a scenario whose UDPDriverController entities are driven over UDP by clients written for \
esmini 3.6.0, then write the run as CommonRoad (as `osc2cr convert` writes it).

Protocol (esmini's ControllerUDPDriver, message version 1, little-endian): a header of four \
32-bit unsigned integers — version (1), inputMode, objectId, frameNumber — then the mode's \
fields as 64-bit floats: 1 driverInput (throttle 0..1, brake 0..1, steering angle \
-pi/2..pi/2), 2 stateXYZHPR (x, y, z, h, p, r, speed, wheel angle, dead-reckoning byte), \
3 stateXYH (x, y, h, speed, wheel angle, dead-reckoning byte), 4 stateH (h, speed, wheel angle, \
dead-reckoning byte). Packed as Python's struct.pack packs them, as esmini's C structs, or as \
its whole 88-byte DMMessage: each length is accepted. A datagram with another version, an \
unknown mode or length, another object's id, a number that is not finite, \
or a frameNumber older than one already accepted for the entity is rejected with a message on \
stderr and counts as none; the run goes on.

Ports: an entity's controller property `port`, else the base port plus its esmini object id \
(the scenario's entities in order from 0, inline trailers right after their vehicle). The base \
port is --base-port, else the `basePort` property of the last UDP driver in the scenario, else \
49950. A port opens when its controller is activated; one activated by the Init reads its \
first datagram before the first step, as esmini does. Ports are bound on 127.0.0.1 unless \
--bind says otherwise.

Execution modes (controller property `execMode`): asynchronous (default) reads every datagram \
queued each step and keeps the newest; synchronous reads one datagram per step, waiting up to \
500 ms, then goes on without. Without a new message driver input repeats, a state with dead \
reckoning moves on at its speed and heading, any other state stays where it is.

Pacing: with an asynchronous port the run goes in real time (--realtime-factor F scales it), \
otherwise as fast as the datagrams come (lockstep); --fast never waits.

Driver inputs outside esmini's documented ranges (a negative throttle, as esmini's \
testUDPDriver-follow-trajectory.py sends) are taken as esmini's vehicle takes them — the pedal \
throttle minus brake, clamped to -1..1, the steering angle to -pi/2..pi/2 — and counted per entity.

OSI: --osi-receiver HOST[:PORT] sends each frame's ASAM OSI 3.5 GroundTruth (port 48198 by \
default) as esmini's --osi_receiver_ip does, so esmini's OSI clients (udp_osi_common.py) read it \
unchanged; --osi-file FILE writes the same messages as an OSI trace file.

The run ends at the scenario's stop trigger or --max-time; OUT_DIR/<scenario stem>.xml (or, with \
--format 2024, the three 2024 files) is then written, whole or not at all. Ctrl-C ends the run \
after the current step and writes what has run so far; the summary says it was interrupted.";

#[derive(clap::Args)]
pub(crate) struct ServeArgs {
    /// The OpenSCENARIO scenario (.xosc).
    #[arg(value_name = "SCENARIO")]
    pub scenario: PathBuf,
    /// Serve esmini's UDPDriverController protocol (the protocol served; required).
    #[arg(long)]
    pub udp: bool,
    /// Output folder (created if missing) for <scenario stem>.xml.
    #[arg(short, long, value_name = "OUT_DIR")]
    pub output: PathBuf,
    /// Address the ports are bound on (0.0.0.0: every interface, as esmini binds).
    #[arg(long, default_value = "127.0.0.1", value_name = "ADDRESS")]
    pub bind: IpAddr,
    /// Base port: an entity without a `port` property listens on it plus its esmini object id
    /// (default: the scenario's `basePort`, else 49950).
    #[arg(long, value_name = "PORT", allow_negative_numbers = true, value_parser = crate::shared_options::whole::<u16>)]
    pub base_port: Option<u16>,
    /// Simulated seconds per wall-clock second (default: 1 when a port is asynchronous, else
    /// as fast as the datagrams come).
    #[arg(long, value_name = "F", conflicts_with = "fast", allow_negative_numbers = true)]
    pub realtime_factor: Option<f64>,
    /// Never wait for the wall clock (synchronous ports still wait for their datagrams).
    #[arg(long)]
    pub fast: bool,
    #[command(flatten)]
    pub run: RunArgs,
    #[command(flatten)]
    pub output_file: CommonRoadArgs,
    /// The ego entity, by exact name (default: the first entity driven over UDP).
    #[arg(long, value_name = "NAME")]
    pub ego: Option<String>,
    /// Write a JSON report: ports, datagrams per entity, every rejection, warnings.
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Print every warning of the conversion on stderr.
    #[arg(short, long)]
    pub verbose: bool,
    #[command(flatten)]
    pub osi: crate::serve_extra::ServeOsiArgs,
}

/// Tells on stderr what the server does.
struct Stderr;

impl Observer for Stderr {
    fn listening(&mut self, l: &Listening) {
        let mode = match l.exec {
            udp::ExecMode::Synchronous => "synchronous: each step waits up to 500 ms for its datagram",
            udp::ExecMode::Asynchronous => "asynchronous: each step takes the newest datagram",
        };
        eprintln!("listening for `{}` (esmini object id {}) on udp {}, {mode}", l.entity, l.object_id, l.address);
    }
    fn rejected(&mut self, r: &Rejection) {
        eprintln!("warning: {r}");
    }
}

fn options(args: &ServeArgs) -> Result<ServeOptions, Failure> {
    let convert = ConvertOptions {
        dt: args.output_file.dt,
        ego: match &args.ego {
            Some(n) => EgoChoice::Name(n.clone()),
            None => ConvertOptions::default().ego,
        },
        drop_ego: args.output_file.drop_ego,
        date: args.output_file.date,
        format: args.osi.format,
        ..args.run.convert_options()
    };
    convert.check().map_err(Failure::input)?;
    let pace = match (args.realtime_factor, args.fast) {
        (Some(f), _) if !(f.is_finite() && f > 0.0) => return Err(Failure::input(format!("--realtime-factor must be a positive number, got {f}"))),
        (Some(f), _) => Some(Pace::RealTime(f)),
        (None, true) => Some(Pace::AsFastAsPossible),
        (None, false) => None,
    };
    let osi_receiver = args.osi.osi_receiver.as_deref().map(osi::receiver_address).transpose().map_err(Failure::input)?;
    Ok(ServeOptions { convert, bind: args.bind, base_port: args.base_port, pace, osi: args.osi.osi_file.is_some(), osi_receiver, ..ServeOptions::default() })
}

pub(crate) fn run(args: &ServeArgs) -> Result<(), Failure> {
    if !args.udp {
        return Err(Failure::input("say which protocol to serve: --udp (esmini's UDPDriverController)"));
    }
    let mut options = options(args)?;
    options.stop = Some(crate::serve_extra::interrupt_flag()?);
    let trace = args.osi.osi_file.as_deref().map(osi::TraceWriter::create).transpose().map_err(|m| Failure { message: m, status: 1 })?;
    let mut observer = crate::serve_extra::WithTrace { inner: &mut Stderr, trace, error: None };
    let served = udp::serve(&args.scenario, &options, &mut observer);
    // a run that did not start writes no trace file (the writer's temporary file goes)
    let osi_file = if served.is_ok() { crate::serve_extra::finish_trace(observer)? } else { None };
    let outcome = served.map_err(|e| {
        let status = match &e {
            udp::Error::Start(f) if matches!(f.stage, Stage::Load | Stage::RoadNetwork) => 2,
            udp::Error::Setup(_) | udp::Error::Bind(_) => 2,
            _ => 1,
        };
        Failure { message: format!("{}: {e}", args.scenario.display()), status }
    })?;

    for n in &outcome.notes {
        eprintln!("note: {n}");
    }
    if args.verbose {
        for w in &outcome.warnings {
            eprintln!("warning: {:?}: {}", w.stage, w.message);
        }
    }
    let interrupted = if outcome.interrupted { ", interrupted (Ctrl-C): the run so far" } else { "" };
    println!("served {}: {} steps to {:.2} s ({}){interrupted}", args.scenario.display(), outcome.steps, outcome.time, outcome.pace);
    for e in &outcome.entities {
        println!(
            "  {}  {}  {}  datagrams {}  accepted {}  superseded {}  rejected {}  clamped {}  steps without a message {}",
            e.name,
            e.address.as_deref().unwrap_or("(never activated)"),
            e.exec.name(),
            e.datagrams,
            e.accepted,
            e.superseded,
            e.rejected,
            e.clamped,
            e.steps_without_message
        );
    }
    if outcome.entities.is_empty() {
        eprintln!("note: no entity of the scenario has a UDPDriverController: nothing was served");
    }
    if let Some(path) = &args.report {
        let json = serde_json::to_vec_pretty(&outcome).map_err(|e| Failure::input(format!("report: {e}")))?;
        commonroad::xml::write_atomic(path, &json).map_err(|e| Failure { message: e.to_string(), status: 1 })?;
    }
    for e in outcome.entities.iter().filter(|e| e.clamped > 0) {
        eprintln!(
            "warning: `{}`: {} messages had driver input outside esmini's ranges (pedals 0..1, steering -pi/2..pi/2): taken as esmini's vehicle takes them, throttle - brake clamped to -1..1",
            e.name, e.clamped
        );
    }
    if let Some(p) = &osi_file {
        eprintln!("wrote {} ({} OSI GroundTruth messages)", p.display(), outcome.osi_frames);
    }
    let path = crate::serve_extra::write_commonroad(&outcome, &args.output, args.osi.format)?;
    let warnings = outcome.warnings.len();
    eprintln!("wrote {}{}", path.display(), if warnings > 0 && !args.verbose { format!(" ({warnings} warnings, -v lists them)") } else { String::new() });
    Ok(())
}

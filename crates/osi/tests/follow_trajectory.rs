//! esmini's own driver-model example closes the loop through osc2cr: esmini 3.6.0's
//! `testUDPDriver-follow-trajectory.py` (unchanged, from `scripts/udp_driver/` of the esmini
//! mirror, with its `follow_trajectory.xosc` and the release's catalogs) reads each frame's OSI
//! GroundTruth from port 48198 with `udp_osi_common.py`'s `OSIReceiver`, steers Car0 along its
//! zigzag and sends driver input — a negative throttle among it — to Car0's UDPDriverController
//! (synchronous, base port 53995, as the scenario's parameters say). The same client drives
//! esmini 3.6.0 (`--osi_receiver_ip`, `--fixed_timestep 0.01`: the same lockstep), and Car0's
//! OSI positions of the two runs agree within 0.5 m at every frame.

use std::net::{SocketAddr, UdpSocket};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use prost::Message;

use crate::common::*;

/// Simulated time driven, s (the client never stops by itself).
const DRIVEN: f64 = 40.0;

/// The client, started in `dir`, its output in `log`; waits until it listens on 48198.
fn client(dir: &Path, log: &Path) -> Child {
    let out = std::fs::File::create(log).expect("log");
    let child =
        Command::new(python()).arg("testUDPDriver-follow-trajectory.py").current_dir(dir).stdout(out).stderr(Stdio::null()).spawn().expect("the client starts");
    let start = Instant::now();
    // the port is taken once the client listens
    while UdpSocket::bind(("127.0.0.1", osi::OSI_PORT)).is_ok() && start.elapsed() < Duration::from_secs(30) {
        std::thread::sleep(Duration::from_millis(50));
    }
    child
}

fn stop(mut c: Child) {
    let _ = c.kill();
    let _ = c.wait();
}

/// Car0's (x, y) in each message of a trace file's complete messages.
fn positions(bytes: &[u8]) -> Vec<(f64, f64, f64)> {
    let mut out = Vec::new();
    let mut rest = bytes;
    while let Some((len, body)) = rest.split_first_chunk::<4>() {
        let n = u32::from_le_bytes(*len) as usize;
        let Some(m) = body.get(..n) else { break };
        let gt = osi::osi3::GroundTruth::decode(m).expect("a GroundTruth");
        let t = gt.timestamp.map_or(0.0, |t| t.seconds.unwrap_or(0) as f64 + f64::from(t.nanos.unwrap_or(0)) * 1e-9);
        let p = gt.moving_object.first().and_then(|o| o.base.as_ref()).and_then(|b| b.position).expect("Car0's position");
        out.push((t, p.x.unwrap_or(0.0), p.y.unwrap_or(0.0)));
        rest = &body[n..];
    }
    out
}

struct Collect(Vec<u8>);
impl udp::Observer for Collect {
    fn osi_frame(&mut self, m: &[u8]) {
        self.0.extend_from_slice(&(m.len() as u32).to_le_bytes());
        self.0.extend_from_slice(m);
    }
}

/// Runs esmini on `xosc` with the client until its trace holds `frames` messages.
fn esmini_run(esmini: &Path, xosc: &Path, dir: &Path, trace: &Path, frames: usize) -> Vec<u8> {
    let mut e = testkit::esmini_command(esmini, 0.01, xosc)
        .args(["--osi_receiver_ip", "127.0.0.1", "--osi_file"])
        .arg(trace)
        .current_dir(dir)
        .spawn()
        .expect("esmini starts");
    let start = Instant::now();
    while positions(&std::fs::read(trace).unwrap_or_default()).len() < frames && start.elapsed() < Duration::from_secs(120) {
        std::thread::sleep(Duration::from_millis(100));
    }
    let _ = e.kill();
    let _ = e.wait();
    std::fs::read(trace).unwrap_or_default()
}

#[test]
fn esminis_follow_trajectory_client_drives_osc2cr_as_it_drives_esmini() {
    let _ports = crate::UDP_PORTS.lock();
    let Some(esmini) = testkit::esmini(true) else { return };
    let dir = work_dir("follow_trajectory");
    let Some(tree) = esmini_files(&dir.join("esmini"), &["scripts/udp_driver", "resources/xosc/Catalogs"]) else { return };
    let scripts: PathBuf = tree.join("scripts/udp_driver");
    let xosc = scripts.join("follow_trajectory.xosc");

    // osc2cr
    let c = client(&scripts, &dir.join("client_osc2cr.log"));
    let receiver: SocketAddr = "127.0.0.1:48198".parse().expect("address");
    let options = udp::ServeOptions {
        convert: convert::ConvertOptions { max_time: DRIVEN, ..Default::default() },
        osi: true,
        osi_receiver: Some(receiver),
        ..Default::default()
    };
    let mut frames = Collect(Vec::new());
    let started = Instant::now();
    let outcome = udp::serve(&xosc, &options, &mut frames);
    let wall = started.elapsed();
    stop(c);
    let outcome = outcome.expect("served");
    let car = outcome.entity("Car0").expect("Car0 served");
    eprintln!(
        "osc2cr: {} steps in {wall:.1?}; Car0: {} datagrams, {} accepted, {} clamped, {} steps without a message",
        outcome.steps, car.datagrams, car.accepted, car.clamped, car.steps_without_message
    );
    assert_eq!(car.exec, udp::ExecMode::Synchronous, "the scenario's execMode");
    assert!(car.rejected == 0 && car.accepted >= outcome.steps - 1, "every step driven by the client: {} of {}", car.accepted, outcome.steps);
    assert!(car.clamped > 0, "the client's negative throttle is taken (clamped) and counted");
    let ours = positions(&frames.0);
    assert_eq!(ours.len(), outcome.steps + 1, "one message per frame");

    // esmini
    let c = client(&scripts, &dir.join("client_esmini.log"));
    let theirs = positions(&esmini_run(&esmini, &xosc, &scripts, &dir.join("esmini.osi"), ours.len()));
    stop(c);
    assert!(theirs.len() >= ours.len(), "esmini's run is as long: {} frames", theirs.len());

    let mut worst = (0.0f64, 0.0f64);
    for (a, b) in ours.iter().zip(&theirs) {
        assert!((a.0 - b.0).abs() < 1e-6, "frame times {} and {}", a.0, b.0);
        let d = (a.1 - b.1).hypot(a.2 - b.2);
        if d > worst.0 {
            worst = (d, a.0);
        }
    }
    let last = ours.last().copied().unwrap_or_default();
    eprintln!("Car0 over {DRIVEN} s: largest distance to esmini's {:.3e} m at {:.2} s; ends at ({:.1}, {:.1})", worst.0, worst.1, last.1, last.2);
    assert!(worst.0 < 0.5, "Car0 {:.3} m from esmini's at {:.2} s", worst.0, worst.1);
    assert!(last.1 > 200.0, "the client drove Car0 along the zigzag: it ended at x = {:.1}", last.1);
}

//! `osc2cr serve --udp` end to end: the shipped example served on 127.0.0.1 to a client that
//! waits for the port to open and then sends esmini UDP driver messages (XYH states, a wrong
//! version and another object's id among them); the wrong ones are reported on stderr, the run
//! goes to its end, the summary counts the datagrams, and the CommonRoad file is written where
//! `convert` writes it, the ego ending where the states put it. Bad usage exits with status 2.

use crate::common::*;

use std::io::{BufRead, BufReader, Read};
use std::net::UdpSocket;
use std::process::{Command, Stdio};

fn example() -> std::path::PathBuf {
    testkit::workspace_root().join("examples/udp_driver.xosc")
}

fn free_port() -> u16 {
    UdpSocket::bind("127.0.0.1:0").and_then(|s| s.local_addr()).expect("a free port").port()
}

/// An esmini stateXYH message (version 1, mode 3), little-endian, packed.
fn xyh(version: u32, object_id: u32, frame: u32, x: f64, y: f64) -> Vec<u8> {
    let mut b: Vec<u8> = [version, 3, object_id, frame].iter().flat_map(|v| v.to_le_bytes()).collect();
    for v in [x, y, 0.0, 0.0, 0.0] {
        b.extend(v.to_le_bytes());
    }
    b.push(0);
    b
}

#[test]
fn serve_drives_the_example_over_udp_and_writes_the_run() {
    let dir = tmp("serve", "example");
    let (out, report) = (dir.join("out"), dir.join("report.json"));
    let port = free_port();
    let mut child = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .args(["serve", s(&example()), "--udp", "-o", s(&out), "--base-port", &port.to_string()])
        .args(["--step", "0.05", "--max-time", "2", "--report", s(&report)])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("osc2cr starts");
    let mut stderr = BufReader::new(child.stderr.take().expect("stderr"));
    let mut said = String::new();
    // wait for the port to open (the line says so), then send every frame at once: the port is
    // synchronous, so the steps read them one by one, in order
    loop {
        let mut line = String::new();
        assert!(stderr.read_line(&mut line).expect("stderr readable") > 0, "osc2cr ended before listening: {said}");
        said.push_str(&line);
        if line.starts_with("listening for `Ego` (esmini object id 0) on udp 127.0.0.1:") {
            assert!(line.contains(&format!(":{port}, synchronous")), "{line}");
            break;
        }
    }
    let client = UdpSocket::bind("127.0.0.1:0").expect("client");
    for k in 0..=45u32 {
        let m = match k {
            10 => xyh(2, 0, k, 100.0, -1.75),
            20 => xyh(1, 1, k, 100.0, -1.75),
            _ => xyh(1, 0, k, 100.0, -1.75),
        };
        client.send_to(&m, ("127.0.0.1", port)).expect("sent");
    }
    stderr.read_to_string(&mut said).expect("stderr read");
    let mut stdout = String::new();
    child.stdout.take().expect("stdout").read_to_string(&mut stdout).expect("stdout read");
    let status = child.wait().expect("osc2cr ends");
    assert!(status.success(), "{status:?}: {said}");

    let prefix = format!("warning: port {port} (`Ego`) at ");
    assert!(said.contains(&prefix) && said.contains("datagram rejected: message version 2; only version 1 is understood"), "{said}");
    assert!(said.contains(&format!("datagram rejected: objectId 1, expected 0: port {port} serves `Ego`, esmini object id 0")), "{said}");
    let written = out.join("udp_driver.xml");
    assert!(said.contains(&format!("wrote {}", written.display())), "{said}");
    assert!(stdout.starts_with(&format!("served {}: 40 steps to 2.00 s (as fast as possible)", example().display())), "{stdout}");
    // (41 datagrams read when the Init frame's read catches the first, else 40)
    assert!(
        stdout.contains(&format!("  Ego  127.0.0.1:{port}  synchronous  datagrams "))
            && stdout.contains("superseded 0  rejected 2  clamped 0  steps without a message 2"),
        "{stdout}"
    );

    // the file convert would write: the ego held where the states put it (box centre 1.4 m ahead)
    let read = commonroad::xml::read_scenario_file(&written).expect("a CommonRoad file");
    let ego = read.scenario.dynamic_obstacles.iter().find(|o| (o.initial_state.x - 21.4).abs() < 1e-6).expect("the ego's obstacle");
    let last = ego.trajectory.last().expect("a trajectory");
    assert_eq!(last.time_step, 20);
    assert!((last.x - 101.4).abs() < 1e-6 && (last.y + 1.75).abs() < 1e-6 && last.velocity == 0.0, "{last:?}");
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&report).expect("report written")).expect("JSON");
    assert_eq!(json["rejections"].as_array().map(Vec::len), Some(2));
    assert_eq!(json["entities"][0]["address"], format!("127.0.0.1:{port}"));
}

#[test]
fn serve_refuses_bad_usage_with_status_2() {
    let dir = tmp("serve", "refused");
    let out = dir.join("out");
    let o = osc2cr(&["serve", s(&example()), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--udp"));
    let o = osc2cr(&["serve", s(&dir.join("missing.xosc")), "--udp", "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
    let taken = UdpSocket::bind("127.0.0.1:0").expect("a socket");
    let port = taken.local_addr().expect("address").port().to_string();
    let o = osc2cr(&["serve", s(&example()), "--udp", "-o", s(&out), "--base-port", &port]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains(&format!("cannot listen on 127.0.0.1:{port} for `Ego`")), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(!out.exists(), "nothing is written when the run cannot start");
}

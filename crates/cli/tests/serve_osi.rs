//! The closed loop's outputs besides the CommonRoad XML: Ctrl-C ends a served run and the run so
//! far is written (CommonRoad and the OSI trace, one message per frame run), the summary saying
//! it was interrupted; `serve --format 2024` writes the three 2024 files; `map --format 2024`
//! writes the map file `convert --format 2024` writes for a scenario on that road (same bytes,
//! same id).

use crate::common::*;

use std::net::UdpSocket;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn udp_example() -> std::path::PathBuf {
    testkit::workspace_root().join("examples/udp_driver.xosc")
}

fn free_port() -> u16 {
    UdpSocket::bind("127.0.0.1:0").and_then(|s| s.local_addr()).expect("a free port").port()
}

/// Messages of an OSI trace file (4-byte little-endian length before each).
fn messages(bytes: &[u8]) -> usize {
    let (mut n, mut rest) = (0, bytes);
    while let Some((len, body)) = rest.split_first_chunk::<4>() {
        let len = u32::from_le_bytes(*len) as usize;
        assert!(len <= body.len(), "message {n} cut off");
        rest = &body[len..];
        n += 1;
    }
    n
}

#[test]
fn ctrl_c_ends_a_served_run_and_writes_the_run_so_far() {
    let dir = tmp("serve_osi", "ctrl_c");
    let (out, trace) = (dir.join("out"), dir.join("run.osi"));
    // no client: the synchronous port waits 500 ms each step, so the run would take minutes
    let child = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .args(["serve", s(&udp_example()), "--udp", "-o", s(&out), "--base-port", &free_port().to_string(), "--osi-file", s(&trace)])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("osc2cr starts");
    std::thread::sleep(Duration::from_millis(2500));
    // SAFETY: kill(2) on the child's pid, which is alive (it waits on its port)
    let sent = unsafe { libc::kill(child.id() as libc::pid_t, libc::SIGINT) };
    assert_eq!(sent, 0, "SIGINT sent");
    let started = Instant::now();
    let output = child.wait_with_output().expect("osc2cr ends");
    assert!(started.elapsed() < Duration::from_secs(5), "ended within a step of Ctrl-C");
    let (stdout, stderr) = (String::from_utf8_lossy(&output.stdout), String::from_utf8_lossy(&output.stderr));
    assert!(output.status.success(), "{stdout}{stderr}");
    assert!(stdout.contains("interrupted (Ctrl-C): the run so far"), "{stdout}");
    let steps: usize =
        stdout.split("served ").nth(1).and_then(|l| l.split(": ").nth(1)).and_then(|l| l.split(' ').next()).and_then(|n| n.parse().ok()).expect("steps");
    assert!((2..=8).contains(&steps), "about one step per 500 ms: {steps}");
    let xml = std::fs::read_to_string(out.join("udp_driver.xml")).expect("the CommonRoad file of the run so far");
    assert!(xml.contains("<dynamicObstacle"), "{xml}");
    assert_eq!(messages(&std::fs::read(&trace).expect("the OSI trace")), steps + 1, "one OSI message per frame run, the Init frame's too");
}

#[test]
fn serve_writes_the_2024_format() {
    let dir = tmp("serve_osi", "format_2024");
    let out = dir.join("out");
    // no client: each of the 5 steps waits 500 ms for its datagram
    let o = osc2cr(&["serve", s(&udp_example()), "--udp", "-o", s(&out), "--base-port", &free_port().to_string(), "--max-time", "0.05", "--format", "2024"]);
    assert_ok(&o);
    let names: Vec<String> = files(&out).iter().map(|p| p.file_name().unwrap_or_default().to_string_lossy().into_owned()).collect();
    assert!(names.contains(&"udp_driver-SC.pb".to_string()) && names.contains(&"udp_driver.pb".to_string()), "{names:?}");
    let map: Vec<&String> = names.iter().filter(|n| n.starts_with("ZAM_") && n.ends_with("-1.pb")).collect();
    assert_eq!(map.len(), 1, "one map file: {names:?}");
    let scenario = std::fs::read(out.join("udp_driver-SC.pb")).expect("scenario file");
    let id = map[0].trim_end_matches(".pb");
    assert!(scenario.windows(id.len()).any(|w| w == id.as_bytes()), "the scenario file names its map {id}");
}

#[test]
fn map_writes_the_2024_map_convert_writes() {
    let dir = tmp("serve_osi", "map_2024");
    let root = testkit::workspace_root();
    let map_file = dir.join("two_lane_curve.pb");
    let o = osc2cr(&["map", s(&root.join("examples/two_lane_curve.xodr")), "-o", s(&map_file), "--format", "2024"]);
    assert_ok(&o);
    let id = String::from_utf8_lossy(&o.stdout).trim().to_string();
    assert!(id.starts_with("ZAM_") && id.ends_with("-1"), "the map id on stdout: {id}");
    let out = dir.join("converted");
    assert_ok(&osc2cr(&["convert", s(&root.join("examples/cut_in.xosc")), "-o", s(&out), "--format", "2024"]));
    let converted = std::fs::read(out.join(format!("{id}.pb"))).expect("convert wrote the map of that id");
    assert_eq!(std::fs::read(&map_file).expect("map file"), converted, "the same map bytes");
}

//! The oracle: esmini 3.6.0 itself (`../shared/tools/esmini`, built with its UDP driver) runs
//! `one_car.xosc` headless with a fixed step of 0.01 s, its Ego's UDPDriverController in
//! synchronous mode, while a client sends it the same datagrams osc2cr gets — driver input that
//! varies every frame (throttle, a spell of braking, steering), and for a second run states of
//! every kind with and without dead reckoning. Ego's trajectory in esmini's CSV log and in
//! osc2cr's run agree at every logged step (the CSV has 6 decimals). Skipped with a notice when
//! esmini cannot run here (Linux only: the client waits for esmini's port in /proc/net/udp).

use crate::common::*;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use udp::serve;

/// esmini, where it runs and `/proc/net/udp` tells when its port is open.
fn esmini() -> Option<PathBuf> {
    let bin = testkit::esmini(false)?;
    if !Path::new("/proc/net/udp").exists() {
        eprintln!("notice: /proc/net/udp is missing here; oracle comparison skipped");
        return None;
    }
    Some(bin)
}

/// Whether a UDP socket is bound to `port` on this machine.
fn bound(port: u16) -> bool {
    let hex = format!(":{port:04X}");
    ["/proc/net/udp", "/proc/net/udp6"]
        .iter()
        .any(|f| std::fs::read_to_string(f).is_ok_and(|t| t.lines().skip(1).any(|l| l.split_whitespace().nth(1).is_some_and(|a| a.ends_with(&hex)))))
}

/// Ego's rows in esmini's CSV log: (time, x, y, z, heading, speed).
fn esmini_rows(csv: &str) -> Vec<[f64; 6]> {
    csv.lines()
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').map(str::trim).collect();
            if f.get(2) != Some(&"Ego") {
                return None;
            }
            let n = |i: usize| f.get(i).and_then(|v| v.parse::<f64>().ok());
            Some([n(1)?, n(13)?, n(14)?, n(15)?, n(26)?, n(4)?])
        })
        .collect()
}

/// Runs esmini on `one_car.xosc` (Ego on `port`, synchronous, `duration` s) with `datagrams`
/// sent once its port is open; Ego's rows.
fn run_esmini(bin: &Path, dir: &Path, port: u16, duration: f64, datagrams: &[Vec<u8>]) -> Vec<[f64; 6]> {
    std::fs::create_dir_all(dir).expect("work dir");
    std::fs::copy(fixture("straight.xodr"), dir.join("straight.xodr")).expect("map copied");
    let text = std::fs::read_to_string(fixture("one_car.xosc")).expect("fixture");
    let text = text
        .replace(r#"name="Port" parameterType="int" value="0""#, &format!(r#"name="Port" parameterType="int" value="{port}""#))
        .replace(r#"name="Duration" parameterType="double" value="1""#, &format!(r#"name="Duration" parameterType="double" value="{duration}""#));
    let xosc = dir.join("one_car.xosc");
    std::fs::write(&xosc, text).expect("scenario written");
    let csv = dir.join("esmini.csv");
    let mut child = testkit::esmini_command(bin, 0.01, &xosc)
        .args(["--seed", "0", "--disable_stdout", "--csv_logger"])
        .arg(&csv)
        .current_dir(dir)
        .spawn()
        .expect("esmini starts");
    let start = Instant::now();
    while !bound(port) {
        assert!(start.elapsed() < Duration::from_secs(20), "esmini did not open port {port}");
        std::thread::sleep(Duration::from_millis(1));
    }
    let client = std::net::UdpSocket::bind("127.0.0.1:0").expect("client");
    for d in datagrams {
        client.send_to(d, ("127.0.0.1", port)).expect("sent");
    }
    assert!(child.wait().expect("esmini ends").success());
    esmini_rows(&std::fs::read_to_string(&csv).expect("esmini's log"))
}

/// osc2cr on the same scenario with the same datagrams, one a frame while they last (then
/// none: each step waits for nothing, briefly); Ego's rows.
fn run_osc2cr(duration: f64, datagrams: &[Vec<u8>]) -> Vec<[f64; 6]> {
    let port = free_port();
    let mut o = options(&[("Port", port.to_string()), ("ExecMode", "synchronous".into())], 60.0);
    o.convert.parameters.retain(|(n, _)| n != "Duration");
    o.convert.parameters.push(("Duration".into(), duration.to_string()));
    o.synchronous_timeout = Duration::from_millis(20);
    let mut client = Lockstep::one_each("Ego", datagrams.to_vec());
    let outcome = serve(&fixture("one_car.xosc"), &o, &mut client).expect("serves");
    let ego = outcome.entity("Ego").expect("served");
    ego.states.iter().map(|(t, s)| [*t, s.x, s.y, s.z, s.h, s.speed]).collect()
}

/// The largest difference in x, y, z, heading and speed over the rows both have after time 0
/// (osc2cr's row at time 0 is recorded before any datagram is read), and how many compared.
fn worst(esmini: &[[f64; 6]], ours: &[[f64; 6]]) -> (f64, usize) {
    let mut worst = 0.0f64;
    let mut n = 0;
    for e in esmini.iter().filter(|e| e[0] > 0.005) {
        let o = ours.iter().find(|o| (o[0] - e[0]).abs() < 1e-6).unwrap_or_else(|| panic!("osc2cr has no row at {}", e[0]));
        let dh = ((o[4] - e[4] + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU) - std::f64::consts::PI).abs();
        worst = [o[1] - e[1], o[2] - e[2], o[3] - e[3], dh, o[5] - e[5]].iter().fold(worst, |w, d| w.max(d.abs()));
        n += 1;
    }
    (worst, n)
}

#[test]
fn esmini_and_osc2cr_drive_ego_the_same_way() {
    let Some(bin) = esmini() else { return };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("udp-esmini-oracle");
    let duration = 2.0;
    // one datagram a frame, and one more for the frame in which the stop trigger fires
    let frames = (duration / 0.01) as u32 + 3;

    let driving: Vec<Vec<u8>> = (0..frames)
        .map(|k| {
            let t = k as f64;
            let brake = if (80..100).contains(&k) { 0.6 } else { 0.0 };
            driver(0, k, 0.5 + 0.5 * (0.05 * t).sin(), brake, 0.25 * (0.03 * t).sin())
        })
        .collect();
    compare(&bin, &dir.join("driver"), "driver input", duration, &driving, 200);

    // states of every kind, 20 frames each: XYH and H with dead reckoning, XYH without, XYZHPR
    // off the road, XYZHPR whose dead-reckoning flag is set but whose roll's lowest byte is 0
    // (esmini reads the flag there: no dead reckoning) — then no datagram for the last four
    // steps (esmini waits 500 ms for each): it stays, its speed 0
    let states: Vec<Vec<u8>> = (0..98u32)
        .map(|k| {
            let t = k as f64 * 0.01;
            match k / 20 {
                0 => xyh(0, k, 60.0 + 8.0 * t, -1.75 + 0.5 * t, 0.06, 8.0, 1),
                1 => state_h(0, k, 0.1, 6.0, 1),
                2 => xyh(0, k, 70.0 + 3.0 * t, -5.25, 0.0, 3.0, 0),
                3 => xyzhpr(0, k, [80.0 + 5.0 * t, -3.0, 0.4, 0.1, 0.02, 0.01, 5.0, 0.0], 0),
                _ => xyzhpr(0, k, [90.0 + 5.0 * t, -3.0, 0.0, -0.05, 0.0, 0.0, 5.0, 0.0], 1),
            }
        })
        .collect();
    compare(&bin, &dir.join("states"), "states, then a hold", 1.0, &states, 100);
    // XYZHPR whose flag is 0 but whose roll's lowest byte is not: esmini dead-reckons after it,
    // here backwards (its speed then derived from the displacement: positive)
    let states: Vec<Vec<u8>> = (0..28u32).map(|k| xyzhpr(0, k, [90.0 - 0.05 * k as f64, -3.0, 0.0, 0.2, 0.0, 0.001, -5.0, 0.0], 0)).collect();
    compare(&bin, &dir.join("dead_reckoning"), "XYZHPR dead reckoning", 0.3, &states, 30);
}

fn compare(bin: &Path, dir: &Path, what: &str, duration: f64, datagrams: &[Vec<u8>], rows: usize) {
    let theirs = run_esmini(bin, dir, free_port(), duration, datagrams);
    let ours = run_osc2cr(duration, datagrams);
    let (w, n) = worst(&theirs, &ours);
    eprintln!("{what}: {n} rows compared, largest difference {w:.2e}");
    assert!(n >= rows && w < 2e-6, "{what}: {n} rows, largest difference {w}");
}

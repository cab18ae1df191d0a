//! `osc2cr simulate` end to end on a corpus scenario: the trace has the conformance header and
//! one row per entity per step; bad arguments exit with status 2.

use std::path::Path;
use std::process::Command;

#[test]
fn simulate_writes_trace_and_events() {
    let Some(shared) = testkit::shared_dir() else { return };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli-simulate");
    std::fs::create_dir_all(&dir).expect("mkdir");
    let (trace, events) = (dir.join("t.csv"), dir.join("e.csv"));
    let out = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .args(["simulate"])
        .arg(shared.join("corpus/esmini/xosc/cut-in.xosc"))
        .arg("--trace")
        .arg(&trace)
        .arg("--events")
        .arg(&events)
        .args(["--max-time", "2", "--step", "0.01", "--param", "EgoSpeed=72"])
        .output()
        .expect("run osc2cr");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&trace).expect("trace written");
    let mut lines = text.lines();
    assert!(lines.next().is_some_and(|h| h.starts_with("time,entity,x,y,z,h,speed")));
    // Two entities, 201 steps (0 .. 2 s) unless the storyboard ended earlier.
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 2 * 201);
    // EgoSpeed=72 km/h -> 20 m/s.
    let ego: Vec<&str> = rows.iter().find(|r| r.contains(",Ego,")).expect("ego row").split(',').collect();
    assert_eq!(ego.get(6).copied(), Some("20.0000"));
    assert!(std::fs::read_to_string(&events).expect("events").starts_with("time,element,from,transition,to\n"));
}

#[test]
fn simulate_bad_input_exits_2() {
    let out = Command::new(env!("CARGO_BIN_EXE_osc2cr")).args(["simulate", "/nonexistent/x.xosc", "--trace", "/tmp/never.csv"]).output().expect("run osc2cr");
    assert_eq!(out.status.code(), Some(2));
    let out = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .args(["simulate", "/nonexistent/x.xosc", "--trace", "/tmp/never.csv", "--param", "novalue"])
        .output()
        .expect("run osc2cr");
    assert_eq!(out.status.code(), Some(2));
}

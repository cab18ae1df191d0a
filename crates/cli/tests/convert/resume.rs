//! `osc2cr convert --resume`: a sweep killed half way (SIGKILL to the `osc2cr` process, once
//! some outputs exist) and run again with `--resume` ends with exactly the files of an
//! uninterrupted run — same names, same bytes, no temporary file left — converting only what
//! was missing, and its table and report account for every variation. In both formats.

use crate::common::*;

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn sweep() -> PathBuf {
    testkit::workspace_root().join("examples/sweep/motorway_sweep.xosc")
}

/// The batch: the first `variations` of the sweep example, on two threads.
fn args(out: &Path, format: &str, variations: usize) -> Vec<String> {
    let sweep = sweep();
    ["convert", s(&sweep), "-o", s(out), "--max-variations", &variations.to_string(), "-j", "2", "--format", format].map(String::from).to_vec()
}

fn run(args: &[String]) -> std::process::Output {
    osc2cr(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

/// Complete outputs in `dir`: scenario files (2024, written last) or XML files.
fn outputs_written(dir: &Path, format: &str) -> usize {
    let suffix = if format == "2024" { "-SC.pb" } else { ".xml" };
    std::fs::read_dir(dir).map(|rd| rd.flatten().filter(|e| e.file_name().to_string_lossy().ends_with(suffix)).count()).unwrap_or(0)
}

/// `variations` conversions, killed once `kill_at` outputs exist (enough that a batch takes
/// a few seconds, so it is still running then).
fn killed_and_resumed_run_writes_the_files_of_one_run(format: &str, variations: usize, kill_at: usize) {
    let root = tmp("convert_resume", format);
    let (whole, resumed) = (root.join("whole"), root.join("resumed"));
    let r = run(&args(&whole, format, variations));
    assert_ok(&r);
    let expected = contents(&whole);

    // start the same batch and kill it once some outputs exist
    let mut child = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .args(args(&resumed, format, variations))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("osc2cr starts");
    let start = Instant::now();
    while outputs_written(&resumed, format) < kill_at {
        assert!(start.elapsed() < Duration::from_secs(120), "no outputs after 2 minutes");
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().expect("kill");
    let status = child.wait().expect("wait");
    assert!(!status.success(), "the batch was killed before it ended ({status})");
    let before = outputs_written(&resumed, format);
    assert!(before >= kill_at && before < variations, "{before} of {variations} outputs when killed");

    let table = root.join("resumed.tsv");
    let report = root.join("resumed.json");
    let mut again = args(&resumed, format, variations);
    again.extend(["--resume", "--table", s(&table), "--report", s(&report)].map(String::from));
    let r = run(&again);
    assert_ok(&r);
    let stderr = String::from_utf8_lossy(&r.stderr);
    assert!(stderr.contains("already complete (--resume)"), "{stderr}");

    let got = contents(&resumed);
    assert!(!got.keys().any(|p| p.to_string_lossy().ends_with(".tmp")), "a temporary file is left");
    assert_eq!(got.keys().collect::<Vec<_>>(), expected.keys().collect::<Vec<_>>(), "the same files");
    for (name, bytes) in &expected {
        assert!(got[name] == *bytes, "{} differs from the uninterrupted run's", name.display());
    }

    // every variation accounted for: complete (kept) or converted (this run), in batch order
    let rows: Vec<Vec<String>> = std::fs::read_to_string(&table).expect("table").lines().skip(1).map(|l| l.split('\t').map(String::from).collect()).collect();
    assert_eq!(rows.len(), variations);
    let complete = rows.iter().filter(|r| r[3] == "complete").count();
    let converted = rows.iter().filter(|r| r[3] == "converted").count();
    assert_eq!(complete + converted, variations, "nothing failed");
    // exactly what was there (a 2024 scenario file is written after its dynamic file and map)
    assert_eq!(complete, before, "complete from the killed run");
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[0], k.to_string(), "batch order");
        assert_eq!(row[2], (k + 1).to_string(), "variation index");
        assert!(row[13].contains("EgoSpeed="), "parameters: {row:?}");
    }
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).expect("report")).expect("json");
    assert_eq!(json["scenarios"].as_array().map(Vec::len), Some(variations));
    assert_eq!(json["planned"], variations);
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn a_killed_2024_sweep_resumed_writes_the_files_of_one_run() {
    killed_and_resumed_run_writes_the_files_of_one_run("2024", 600, 80);
}

#[test]
fn a_killed_2020a_sweep_resumed_writes_the_files_of_one_run() {
    // 2020a files are ten times larger (each holds the map): fewer of them
    killed_and_resumed_run_writes_the_files_of_one_run("2020a", 300, 40);
}

#[test]
fn resuming_a_complete_batch_converts_nothing() {
    let out = tmp("convert_resume", "complete");
    let example = testkit::workspace_root().join("examples/cut_in_speeds.xosc");
    let r = osc2cr(&["convert", s(&example), "-o", s(&out), "--format", "2024"]);
    assert_ok(&r);
    let before = contents(&out);
    // a temporary file of a writer that is gone (pid 1 never writes here; a dead pid does)
    let stale = out.join(format!(".cut_in_speeds_2.pb.{}.0.tmp", u32::MAX - 1));
    std::fs::write(&stale, b"partial").expect("write");
    let r = osc2cr(&["convert", s(&example), "-o", s(&out), "--format", "2024", "--resume"]);
    assert_ok(&r);
    let stderr = String::from_utf8_lossy(&r.stderr);
    assert!(stderr.contains("0 converted, 6 already complete"), "{stderr}");
    assert!(stderr.contains("removed 1 temporary file"), "{stderr}");
    assert_eq!(contents(&out), before);
}

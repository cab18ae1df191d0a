//! `osc2cr export` as a user runs it: `--help`, a batch that goes on past a bad file (exit
//! status, summary table, JSON report, maps at the top, written once and shared), the same
//! bytes on a second run and whatever `-j`, no temporary file left.

use crate::common::*;

use super::commonroad_scenarios;

#[test]
fn help_explains_the_command() {
    let r = osc2cr(&["export", "--help"]);
    assert_ok(&r);
    let help = String::from_utf8_lossy(&r.stdout);
    for needle in [
        "2018b",
        "2024",
        "NAME-SC.pb",
        "--osc",
        "1.0",
        "--ego-controller",
        "external",
        "--play-to-end",
        "--report",
        "-j",
        "named by its",
        "traffic-signal controllers",
    ] {
        assert!(help.contains(needle), "--help names {needle:?}:\n{help}");
    }
}

#[test]
fn a_batch_goes_on_past_a_bad_file_and_writes_the_same_bytes_again() {
    let Some(scenarios) = commonroad_scenarios() else { return };
    let bad_dir = tmp("export_cli", "bad-input");
    let bad = bad_dir.join("broken.xml");
    std::fs::write(&bad, "<commonRoad commonRoadVersion=\"2020a\"><lanelet id=\"x\"").expect("write");
    let out = tmp("export_cli", "batch");
    let report = bad_dir.join("report.json");
    let r = osc2cr(&["export", s(&scenarios), s(&bad), "-o", s(&out), "--report", s(&report), "-j", "2"]);
    assert_eq!(r.status.code(), Some(1), "a partial batch: {}", String::from_utf8_lossy(&r.stderr));
    let stderr = String::from_utf8_lossy(&r.stderr);
    assert!(stderr.contains("failed") && stderr.contains("broken.xml"), "{stderr}");
    let table = String::from_utf8_lossy(&r.stdout);
    assert!(table.contains("scenarios") && table.contains("exported") && table.contains("all"), "{table}");

    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).expect("report")).expect("json");
    let scenarios_n = json["scenarios"].as_array().expect("scenarios").len();
    assert_eq!(json["failed"], 1);
    assert_eq!(json["exported"].as_u64(), Some(scenarios_n as u64 - 1));
    // every map is at the top of the output folder, written once, and names what uses it
    let maps = json["maps"].as_array().expect("maps");
    assert!(!maps.is_empty());
    let used: u64 = maps.iter().map(|m| m["scenarios"].as_u64().unwrap_or(0)).sum();
    let with_map = json["scenarios"].as_array().expect("scenarios").iter().filter(|s| s["map"].is_string()).count();
    assert_eq!(used, with_map as u64);
    for m in maps {
        let name = m["file"].as_str().expect("file");
        assert!(out.join(name).is_file(), "{name} at the top");
    }
    // scenarios on the same lanelet network share one map (the test_reading_* files do)
    assert!(maps.iter().any(|m| m["scenarios"].as_u64().unwrap_or(0) >= 2), "a map shared: {maps:?}");
    assert!(maps.len() < with_map, "{} maps for {with_map} scenarios", maps.len());
    // a scenario in a sub-folder names its map relative to itself
    let tutorial = std::fs::read_to_string(out.join("tutorials/ZAM_Tutorial-1_1_T-1.xosc")).expect("tutorial written");
    assert!(tutorial.contains("<LogicFile filepath=\"../ZAM_"), "relative map path");

    let first = contents(&out);
    assert!(first.keys().all(|p| !p.to_string_lossy().ends_with(".tmp")), "no temporary file left");
    let again = tmp("export_cli", "batch-again");
    let r = osc2cr(&["export", s(&scenarios), "-o", s(&again), "-j", "1"]);
    assert_ok(&r);
    assert_eq!(contents(&again), first, "the same input gives the same bytes, whatever -j");
}

#[test]
fn one_bad_file_is_bad_input() {
    let dir = tmp("export_cli", "one-bad");
    let bad = dir.join("nothing.xml");
    std::fs::write(&bad, "not xml").expect("write");
    let r = osc2cr(&["export", s(&bad), "-o", s(&dir.join("out"))]);
    assert_eq!(r.status.code(), Some(2), "{}", String::from_utf8_lossy(&r.stderr));
}

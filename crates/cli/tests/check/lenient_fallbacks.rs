//! What the standard forbids but esmini runs: an error by default, and with `--lenient` read as
//! esmini reads it, each fallback a warning that names it. `data/lenient_fallbacks/fallbacks.xosc`
//! holds the two cases real files have — a parameter whose value is `None` where a number is
//! expected (esmini's `atof`: 0; also "150 m" as a position's s: 150) and
//! `vehicleCategory="EgoCar"` (esmini keeps its default category, car) — on
//! examples/straight_road.xodr. Where esmini 3.6.0 runs, the lenient run is compared with it.

use crate::common::*;

use std::path::{Path, PathBuf};
use std::process::Command;

/// The fixture and its map in a fresh folder; the scenario's path.
fn fixture(name: &str) -> PathBuf {
    let dir = tmp("lenient_fallbacks", name);
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lenient_fallbacks/fallbacks.xosc");
    std::fs::copy(data, dir.join("fallbacks.xosc")).expect("scenario");
    std::fs::copy(testkit::workspace_root().join("examples/straight_road.xodr"), dir.join("straight_road.xodr")).expect("map");
    dir.join("fallbacks.xosc")
}

/// Line and column of the value of the last `attr="…"` of `needle` in the fixture (its first
/// occurrence).
fn at(file: &Path, needle: &str) -> String {
    let text = std::fs::read_to_string(file).expect("scenario");
    let i = text.find(needle).unwrap_or_else(|| panic!("{needle} not in the fixture")) + needle.rfind("=\"").expect("attribute") + 2;
    let line = text[..i].matches('\n').count() + 1;
    let col = text[..i].rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    format!("fallbacks.xosc:{line}:{col}")
}

#[test]
fn check_and_strict_convert_refuse_them_at_their_attributes() {
    let file = fixture("strict");
    let category = at(&file, r#"name="car" vehicleCategory="EgoCar""#);
    let speed = at(&file, r#"<AbsoluteTargetSpeed value="$LeadSpeed""#);
    let s = at(&file, r#"s="$LeadS""#);
    let r = osc2cr(&["check", s_(&file)]);
    let out = String::from_utf8_lossy(&r.stdout);
    assert_eq!(r.status.code(), Some(2), "{out}");
    for place in [&category, &speed, &s] {
        assert!(out.lines().any(|l| l.contains(place.as_str()) && l.contains("error")), "no error at {place}:\n{out}");
    }

    let out_dir = file.with_file_name("out");
    let r = osc2cr(&["convert", s_(&file), "-o", s_(&out_dir)]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert_eq!(r.status.code(), Some(2), "{err}");
    assert!(err.contains(&category) && err.contains(&speed) && err.contains("--lenient"), "{err}");
    assert!(files(&out_dir).is_empty(), "nothing written: {:?}", files(&out_dir));
}

#[test]
fn lenient_convert_reads_them_as_esmini_and_names_each_fallback() {
    let file = fixture("lenient");
    let out_dir = file.with_file_name("out");
    let r = osc2cr(&["convert", s_(&file), "-o", s_(&out_dir), "--lenient", "-v"]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert!(r.status.success(), "{err}");
    for (place, fallback) in [
        (at(&file, r#"name="car" vehicleCategory="EgoCar""#), "found 'EgoCar'; esmini reads it as its default, car"),
        (at(&file, r#"<AbsoluteTargetSpeed value="$LeadSpeed""#), "found 'None' (from '$LeadSpeed'); esmini reads it as 0"),
        (at(&file, r#"s="$LeadS""#), "found '150 m' (from '$LeadS'); esmini reads it as 150"),
    ] {
        assert!(err.lines().any(|l| l.contains(&place) && l.contains(fallback)), "no warning {fallback:?} at {place}:\n{err}");
    }
    assert_eq!(files(&out_dir).len(), 1, "{:?}", files(&out_dir));
}

/// Lead's (x, speed) at `t` in a trace with osc2cr's columns (time,entity,x,y,z,h,speed,…).
fn ours(csv: &str, t: f64) -> Option<(f64, f64)> {
    csv.lines().find_map(|l| {
        let f: Vec<&str> = l.split(',').collect();
        let n = |i: usize| f.get(i).and_then(|v| v.trim().parse::<f64>().ok());
        (f.get(1) == Some(&"Lead") && n(0).is_some_and(|x| (x - t).abs() < 1e-6)).then(|| Some((n(2)?, n(6)?))).flatten()
    })
}

/// The same from esmini's CSV log (index, time, name, id, speed, …, x at column 13).
fn esmini_rows(csv: &str, t: f64) -> Option<(f64, f64)> {
    csv.lines().find_map(|l| {
        let f: Vec<&str> = l.split(',').map(str::trim).collect();
        // one row per frame; Lead's columns follow Ego's (31 per entity)
        let lead = f.iter().position(|v| *v == "Lead")?;
        let n = |i: usize| f.get(i).and_then(|v| v.parse::<f64>().ok());
        n(1).filter(|x| (x - t).abs() < 1e-6)?;
        Some((n(lead + 11)?, n(lead + 2)?))
    })
}

#[test]
fn the_lenient_run_is_esmini_s() {
    let file = fixture("run");
    let trace = file.with_file_name("trace.csv");
    let r = osc2cr(&["simulate", s_(&file), "--trace", s_(&trace), "--lenient"]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    let csv = std::fs::read_to_string(&trace).expect("trace");
    // "150 m" is s = 150 on the straight road; at 1 s the None speed stops the lead car (a step)
    let start = ours(&csv, 0.0).expect("Lead at 0 s");
    let later = ours(&csv, 1.5).expect("Lead at 1.5 s");
    assert!((start.0 - 150.0).abs() < 1e-9 && (start.1 - 8.0).abs() < 1e-9, "{start:?}");
    assert!(later.1.abs() < 1e-9, "{later:?}");

    let Some(shared) = testkit::shared_dir() else { return };
    let bin = shared.join("tools/esmini/bin/esmini-3.6.0");
    let log = file.with_file_name("esmini.csv");
    let ran = Command::new(&bin)
        .current_dir(file.parent().expect("dir"))
        .args(["--headless", "--fixed_timestep", "0.01", "--seed", "0", "--osc", s_(&file), "--csv_logger", s_(&log)])
        .output();
    match ran {
        Ok(o) if o.status.success() && log.exists() => {
            let text = std::fs::read_to_string(&log).expect("esmini log");
            assert!(String::from_utf8_lossy(&o.stdout).contains("Vehicle category EgoCar not supported"), "esmini says it keeps its default");
            for t in [0.0, 1.5] {
                let (e, o) = (esmini_rows(&text, t).expect("esmini row"), ours(&csv, t).expect("our row"));
                assert!((e.0 - o.0).abs() < 1e-3 && (e.1 - o.1).abs() < 1e-3, "t = {t}: esmini {e:?}, osc2cr {o:?}");
            }
        }
        _ => eprintln!("notice: esmini cannot run here ({}); comparison skipped", bin.display()),
    }
}

fn s_(p: &Path) -> &str {
    s(p)
}

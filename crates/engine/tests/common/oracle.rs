//! esmini 3.6.0 as the oracle of a fixture test: a fixture scenario run by the engine and, where
//! esmini can run here (`../shared/tools/esmini`), by esmini too, each entity compared row by row.
//! Where esmini cannot run the comparison is skipped with a notice (the tests also assert
//! esmini's numbers, written down from a confirmed run).

use engine::{Run, Settings};
use std::path::{Path, PathBuf};
use std::process::Command;

/// One row of esmini's CSV log for one entity.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct OracleRow {
    pub time: f64,
    pub entity: String,
    pub x: f64,
    pub y: f64,
    pub h: f64,
    pub speed: f64,
}

/// The fixture `name` (its map named in it, relative to the fixtures) run by the engine.
pub(crate) fn run_fixture_scenario(name: &str, max_time: f64) -> Run {
    let path = super::fixtures().join(name);
    let (scenario, _) = openscenario::load_scenario(&path, &Default::default()).expect("fixture scenario loads");
    let net = scenario.road_network.logic_file.as_ref().map(|p| opendrive::load(p).expect("fixture road loads").network);
    engine::simulate(&scenario, net.as_ref(), &Settings { step: 0.01, max_time }).expect("simulate")
}

fn esmini_binary() -> Option<PathBuf> {
    let bin = testkit::shared_dir()?.join("tools/esmini/bin/esmini-3.6.0");
    let runs = Command::new(&bin).arg("--version").output().is_ok_and(|o| String::from_utf8_lossy(&o.stdout).contains("esmini"));
    runs.then_some(bin)
}

/// esmini's rows for the fixture `name` (fixed step 0.01 s, seed 0), or `None` with a notice.
pub(crate) fn esmini_rows(name: &str) -> Option<Vec<OracleRow>> {
    let Some(bin) = esmini_binary() else {
        eprintln!("notice: esmini 3.6.0 cannot run here; the oracle comparison of {name} is skipped");
        return None;
    };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("esmini-oracle");
    std::fs::create_dir_all(&dir).expect("oracle folder");
    let csv = dir.join(Path::new(name).with_extension("csv"));
    let log = dir.join(Path::new(name).with_extension("log"));
    let status = Command::new(&bin)
        .args(["--headless", "--fixed_timestep", "0.01", "--seed", "0", "--osc"])
        .arg(super::fixtures().join(name))
        .arg("--csv_logger")
        .arg(&csv)
        .arg("--logfile_path")
        .arg(&log)
        .output()
        .expect("esmini starts");
    assert!(status.status.success(), "esmini failed on {name}: {}", String::from_utf8_lossy(&status.stderr));
    Some(parse_esmini_csv(&std::fs::read_to_string(&csv).expect("esmini's log")))
}

/// esmini's wide CSV log (a block of columns per entity) as rows.
fn parse_esmini_csv(text: &str) -> Vec<OracleRow> {
    let mut out = Vec::new();
    let mut layout: Option<(usize, usize, [usize; 4])> = None;
    for line in text.lines() {
        let parts: Vec<&str> = line.split(',').map(str::trim).collect();
        let Some((first, block, cols)) = layout else {
            if parts.get(1).is_some_and(|p| p.starts_with("TimeStamp")) {
                let names: Vec<usize> = parts.iter().enumerate().filter(|(_, p)| p.contains("Entity_Name")).map(|(i, _)| i).collect();
                let first = names[0];
                let block = names.get(1).map_or(parts.len() - first, |n| n - first);
                let find = |key: &str| parts[first..first + block].iter().position(|p| p.contains(key)).expect("esmini column");
                layout = Some((first, block, [find("World_Position_X"), find("World_Position_Y"), find("World_Heading_Angle"), find("Current_Speed")]));
            }
            continue;
        };
        let Ok(time) = parts.get(1).unwrap_or(&"").parse::<f64>() else { continue };
        let mut k = first;
        while k + block <= parts.len() && !parts[k].is_empty() {
            let num = |c: usize| parts[k + c].parse::<f64>().expect("esmini number");
            out.push(OracleRow { time, entity: parts[k].to_string(), x: num(cols[0]), y: num(cols[1]), h: num(cols[2]), speed: num(cols[3]) });
            k += block;
        }
    }
    out
}

/// How far the engine's run is from esmini's rows.
pub(crate) struct Agreement {
    /// The worst distance (m) between positions of any entity at any time both have, and where.
    pub worst: f64,
    pub worst_at: String,
    /// The worst heading difference (rad), and where.
    pub worst_heading: f64,
    pub worst_heading_at: String,
    /// The last time of each run.
    pub ours_end: f64,
    pub esmini_end: f64,
}

/// Compare the engine's run with esmini's rows.
pub(crate) fn against_esmini(run: &Run, rows: &[OracleRow]) -> Agreement {
    let mut a =
        Agreement { worst: 0.0, worst_at: String::new(), worst_heading: 0.0, worst_heading_at: String::new(), ours_end: run.trace.end_time(), esmini_end: 0.0 };
    for r in rows {
        a.esmini_end = a.esmini_end.max(r.time);
        let Some(e) = run.trace.entities.iter().find(|e| e.name == r.entity) else {
            a.worst = f64::INFINITY;
            a.worst_at = format!("{} missing", r.entity);
            return a;
        };
        let k = ((r.time - run.trace.start) / run.trace.step).round() as usize;
        let Some(Some(s)) = e.samples.get(k) else { continue };
        let d = (s.x - r.x).hypot(s.y - r.y);
        if d > a.worst {
            a.worst = d;
            a.worst_at = format!("{} at {:.2} s: ours ({:.3}, {:.3}) esmini ({:.3}, {:.3})", r.entity, r.time, s.x, s.y, r.x, r.y);
        }
        let dh = (s.h - r.h).rem_euclid(std::f64::consts::TAU);
        let dh = dh.min(std::f64::consts::TAU - dh);
        if dh > a.worst_heading {
            a.worst_heading = dh;
            a.worst_heading_at = format!("{} at {:.2} s: ours {:.4} esmini {:.4}", r.entity, r.time, s.h, r.h);
        }
    }
    a
}

/// Assert that the engine's run of fixture `name` is esmini's within `tol` m, 0.01 rad of
/// heading and one step of end time, when esmini can run here.
pub(crate) fn assert_matches_esmini(name: &str, run: &Run, tol: f64) {
    let Some(rows) = esmini_rows(name) else { return };
    let a = against_esmini(run, &rows);
    assert!(a.worst <= tol, "{name}: {:.3} m from esmini ({})", a.worst, a.worst_at);
    assert!(a.worst_heading <= 0.01, "{name}: heading {:.4} rad from esmini's ({})", a.worst_heading, a.worst_heading_at);
    assert!((a.ours_end - a.esmini_end).abs() <= 0.011, "{name}: ends at {:.2} s, esmini at {:.2} s", a.ours_end, a.esmini_end);
}

/// Assert that `entity` is at esmini's pose (x, y, heading) at `t`: within 1 mm and 1 mrad.
pub(crate) fn assert_esmini_pose_at(run: &Run, entity: &str, t: f64, x: f64, y: f64, h: f64) {
    let s = super::at(run, entity, t);
    let dh = (s.h - h).rem_euclid(std::f64::consts::TAU);
    assert!(
        super::close(s.x, x, 1e-3) && super::close(s.y, y, 1e-3) && dh.min(std::f64::consts::TAU - dh) < 1e-3,
        "{entity} at {t} s: ({:.4}, {:.4}, {:.4}), esmini ({x}, {y}, {h})",
        s.x,
        s.y,
        s.h
    );
}

/// esmini's pose of an entity at a time: (entity, t, x, y, heading).
pub(crate) type EsminiPose<'a> = (&'a str, f64, f64, f64, f64);

/// The run of fixture `name` (up to `max_time`), checked against esmini's `poses` (noted from a
/// confirmed run) and, where esmini runs here, against its whole run within 1 mm.
pub(crate) fn assert_fixture_matches_esmini(name: &str, max_time: f64, poses: &[EsminiPose]) -> Run {
    let run = run_fixture_scenario(name, max_time);
    for &(entity, t, x, y, h) in poses {
        assert_esmini_pose_at(&run, entity, t, x, y, h);
    }
    assert_matches_esmini(name, &run, 1e-3);
    run
}

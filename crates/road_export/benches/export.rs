//! Export time per map, and the same maps beside the CommonRoad Scenario Designer's cr2odr
//! (`cargo bench -p osc2cr-road-export --bench export`; release, `../shared` beside the repo).
//!
//! For every acceptance map (the lanelet networks of `../shared/commonroad-scenarios` and of
//! osc2cr's conversions of the corpus) it times our export (median of several runs), reads
//! the result back with osc2cr's map conversion (bound error, relations, area) and has esmini
//! 3.6.0 load it. With `PEER=1` it also makes a virtual environment with crdesigner 0.8.5
//! from the package index under `target/peer` (used by nothing else), runs cr2odr on the same
//! maps (`benches/peer_cr2odr.py`, one process per map) and measures its files the same way.
//! Prints a line per map and the summary table; times are reported as ratios too.

#[path = "../tests/common/mod.rs"]
mod common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const RUNS: usize = 5;

struct Measured {
    ok: bool,
    seconds: Option<f64>,
    error: Option<f64>,
    relations: Option<(usize, usize)>,
    added: Option<f64>,
    esmini: Option<bool>,
    note: String,
}

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v.get(v.len() / 2).copied().unwrap_or_default()
}

/// The round trip of an OpenDRIVE file against the network it was made from.
fn measure(network: &commonroad::LaneletNetwork, xodr: &Path, esmini: Option<&Path>, dir: &Path) -> Measured {
    let mut m = Measured { ok: true, seconds: None, error: None, relations: None, added: None, esmini: None, note: String::new() };
    match opendrive::load(xodr) {
        Ok(l) => {
            let back = map::convert(&l.network, &map::MapOptions::default()).network;
            let c = road_export::round_trip::compare(network, &back);
            m.error = Some(c.worst_bound_error());
            m.relations = Some((c.relations_kept, c.relations));
            m.added = Some(c.added_fraction());
        }
        Err(e) => m.note = format!("osc2cr cannot read it: {e}"),
    }
    m.esmini = esmini.map(|e| common::esmini_loads(e, xodr, dir).is_ok());
    m
}

fn peer_python(root: &Path) -> Option<PathBuf> {
    let venv = root.join("target/peer/venv");
    let py = venv.join("bin/python");
    let ok = |py: &Path| Command::new(py).args(["-c", "import crdesigner"]).output().is_ok_and(|o| o.status.success());
    if ok(&py) {
        return Some(py);
    }
    eprintln!("making {} with crdesigner 0.8.5 …", venv.display());
    let made = Command::new("python3").args(["-m", "venv"]).arg(&venv).status().ok()?;
    let pip = made.success() && Command::new(&py).args(["-m", "pip", "install", "-q", "commonroad-scenario-designer==0.8.5"]).status().ok()?.success();
    (pip && ok(&py)).then_some(py)
}

fn main() {
    let Some(shared) = testkit::shared_dir() else { return };
    let root = testkit::workspace_root();
    let dir = root.join("target/peer");
    let (ours_dir, maps_dir, peer_dir) = (dir.join("ours"), dir.join("maps"), dir.join("out"));
    for d in [&ours_dir, &maps_dir, &peer_dir] {
        std::fs::create_dir_all(d).expect("creates the bench folders");
    }
    let esmini = shared.join("tools/esmini/bin/esmini-3.6.0");
    let esmini = Command::new(&esmini).arg("--help").output().is_ok().then_some(esmini);
    // the maps, each also as a CommonRoad file for the peer
    let mut maps = Vec::new();
    for m in common::scenario_maps(&shared) {
        maps.push(m);
    }
    maps.extend(common::corpus_maps(&shared));
    let date = commonroad::Date::new(2026, 1, 1).expect("date");
    let mut inputs = Vec::new();
    for m in &maps {
        let name: String = m.name.chars().filter(char::is_ascii_alphanumeric).take(40).collect();
        let header = commonroad::Header {
            benchmark_id: commonroad::BenchmarkId::parse(&format!("ZAM_{name}-1_1_T-1")).expect("id"),
            date,
            author: "osc2cr".into(),
            affiliation: String::new(),
            source: "road_export bench".into(),
            time_step_size: 0.1,
        };
        let mut s = commonroad::Scenario::new(header);
        s.network = m.network.clone();
        let file = maps_dir.join(format!("{}.xml", m.name));
        // the writer needs a planning problem (the 2020a schema does); cr2odr ignores it
        let mut ids = s.id_allocator(None);
        let start = m.network.lanelets.first().and_then(|l| l.bounds.left().first().zip(l.bounds.right().first()));
        let (x, y) = start.map_or((0.0, 0.0), |(a, b)| (0.5 * (a.x + b.x), 0.5 * (a.y + b.y)));
        let problems = commonroad::PlanningProblemSet {
            problems: vec![commonroad::PlanningProblem {
                id: ids.planning_problem(),
                initial_state: commonroad::PlanningInitialState { x, y, orientation: 0.0, velocity: 0.0, yaw_rate: 0.0, slip_angle: 0.0, acceleration: None },
                goal_states: vec![commonroad::GoalState {
                    time: commonroad::TimeInterval::new(1, 10).expect("interval"),
                    position: None,
                    orientation: None,
                    velocity: None,
                }],
            }],
        };
        let bytes = commonroad::xml::write_scenario(&s, &problems).expect("writes the map");
        std::fs::write(&file, bytes).expect("writes");
        inputs.push(file);
    }
    // ours
    let mut ours = Vec::new();
    for m in &maps {
        let options = road_export::Options { name: m.name.clone(), ..Default::default() };
        let mut times = Vec::new();
        let mut last = None;
        for _ in 0..RUNS {
            let t = Instant::now();
            last = road_export::export(&m.network, &options).ok();
            times.push(t.elapsed());
        }
        let file = ours_dir.join(format!("{}.xodr", m.name));
        let mut r = match last {
            Some(e) => {
                std::fs::write(&file, &e.xodr).expect("writes");
                measure(&m.network, &file, esmini.as_deref(), &dir)
            }
            None => Measured { ok: false, seconds: None, error: None, relations: None, added: None, esmini: None, note: "export failed".into() },
        };
        r.seconds = Some(median(times).as_secs_f64());
        ours.push(r);
    }
    // the peer
    let mut peer: Vec<Option<Measured>> = maps.iter().map(|_| None).collect();
    if std::env::var_os("PEER").is_some() {
        match peer_python(&root) {
            Some(py) => {
                let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("benches/peer_cr2odr.py");
                let out = Command::new(py).arg(&script).arg(&peer_dir).args(&inputs).output().expect("runs cr2odr");
                let text = String::from_utf8_lossy(&out.stdout);
                for line in text.lines().filter(|l| l.starts_with('{')) {
                    let Ok(v) = serde_json::from_str::<serde_json::Value>(line) else { continue };
                    let Some(k) = inputs.iter().position(|f| f.to_string_lossy() == v["file"].as_str().unwrap_or("")) else { continue };
                    let Some(m) = maps.get(k) else { continue };
                    let ok = v["ok"].as_bool().unwrap_or(false);
                    let mut r = if ok {
                        measure(&m.network, &peer_dir.join(format!("{}.xodr", m.name)), esmini.as_deref(), &dir)
                    } else {
                        Measured { ok: false, seconds: None, error: None, relations: None, added: None, esmini: None, note: String::new() }
                    };
                    r.ok = ok;
                    r.seconds = v["seconds"].as_f64();
                    if !ok {
                        r.note = v["error"].as_str().unwrap_or("").chars().take(90).collect();
                    }
                    peer[k] = Some(r);
                }
            }
            None => eprintln!("notice: no Python environment with crdesigner could be made; the peer is not measured"),
        }
    } else {
        eprintln!("notice: set PEER=1 to measure crdesigner's cr2odr beside the export");
    }
    // the table
    let fmt_err = |m: &Measured| {
        m.error.map_or("—".to_string(), |e| {
            if e >= road_export::round_trip::ERROR_CAP {
                format!(">{}", road_export::round_trip::ERROR_CAP)
            } else {
                format!("{e:.4}")
            }
        })
    };
    let yes = |b: Option<bool>| b.map_or("—", |b| if b { "yes" } else { "NO" });
    println!("| map | lanelets | ours ms | ours err m | ours esmini | cr2odr | cr2odr ms | cr2odr err m | cr2odr esmini | note |");
    println!("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
    let (mut n, mut ours_pass, mut ours_esmini, mut peer_conv, mut peer_esmini, mut peer_pass) = (0, 0, 0, 0, 0, 0);
    let (mut t_ours, mut t_peer, mut ratios) = (0.0, 0.0, Vec::new());
    for ((m, o), p) in maps.iter().zip(&ours).zip(&peer) {
        n += 1;
        let within = |r: &Measured| r.error.is_some_and(|e| e <= 0.05);
        ours_pass += usize::from(within(o));
        ours_esmini += usize::from(o.esmini == Some(true));
        if let Some(p) = p {
            peer_conv += usize::from(p.ok);
            peer_esmini += usize::from(p.esmini == Some(true));
            peer_pass += usize::from(within(p));
            if let (Some(a), Some(b)) = (o.seconds, p.seconds) {
                t_ours += a;
                t_peer += b;
                ratios.push(b / a.max(1e-9));
            }
        }
        println!(
            "| {} | {} | {:.2} | {} | {} | {} | {} | {} | {} | {} |",
            m.name,
            m.network.lanelets.len(),
            1e3 * o.seconds.unwrap_or(0.0),
            fmt_err(o),
            yes(o.esmini),
            p.as_ref().map_or("—", |p| if p.ok { "yes" } else { "NO" }),
            p.as_ref().and_then(|p| p.seconds).map_or("—".to_string(), |s| format!("{:.1}", 1e3 * s)),
            p.as_ref().map_or("—".to_string(), fmt_err),
            yes(p.as_ref().and_then(|p| p.esmini)),
            p.as_ref().map_or(String::new(), |p| p.note.replace('|', "/")),
        );
    }
    ratios.sort_by(f64::total_cmp);
    println!();
    println!("maps: {n}; ours within 0.05 m: {ours_pass}, esmini loads ours: {ours_esmini}");
    if !ratios.is_empty() {
        println!(
            "cr2odr converts {peer_conv}, esmini loads {peer_esmini}, within 0.05 m: {peer_pass}; time on the maps both convert: ours {:.2} s, cr2odr {:.2} s (×{:.1} in total, median ×{:.1} per map)",
            t_ours,
            t_peer,
            t_peer / t_ours.max(1e-9),
            ratios[ratios.len() / 2]
        );
    }
}

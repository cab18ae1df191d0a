//! The simulator round trip (issue 24): every CommonRoad output of the corpus conversions and
//! every scenario of `../shared/commonroad-scenarios`, exported (`--play-to-end`, so that the
//! run covers every obstacle state even after the ego reached its goal) and run by esmini 3.6.0
//! as a user runs it (`--headless --fixed_timestep dt/2 --csv_logger`, a step that lands on
//! every CommonRoad time step; half of it so that an obstacle whose first state is at step 1
//! can be added after time 0 and still be there at step 1): esmini must load each with no error, and every obstacle must be
//! within 0.10 m of its CommonRoad position at every CommonRoad time step in at least 95 % of
//! the scenarios. The others are listed with their worst error and run again with esmini's
//! trajectory filter off (`--traj_filter 0`; by default esmini merges trajectory vertices
//! within 0.1 m of each other, which the export foresees), which tells whether the filter is
//! the reason.
//!
//! esmini runs on all cores; the wall time is printed (the full set takes a few minutes).

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use commonroad::{Scenario, Shape, State};

use crate::common::{acceptance_scenarios, export_batch, fresh_dir, short};

/// The acceptance threshold, m.
const TOLERANCE: f64 = 0.10;
/// Wall-clock limit of one esmini run.
const RUN_LIMIT: Duration = Duration::from_secs(600);

/// One esmini run: where each entity was at each logged step (key: the step number).
pub(crate) struct Log {
    rows: HashMap<u64, HashMap<String, (f64, f64)>>,
}

fn parse_csv(text: &str, step: f64) -> Log {
    let mut rows = HashMap::new();
    for line in text.lines() {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if f.len() < 3 || !f[0].chars().all(|c| c.is_ascii_digit()) || f[0].is_empty() {
            continue;
        }
        let Ok(t) = f[1].parse::<f64>() else { continue };
        let mut entities = HashMap::new();
        let mut i = 2;
        while i + 12 < f.len() && !f[i].is_empty() {
            if let (Ok(x), Ok(y)) = (f[i + 11].parse::<f64>(), f[i + 12].parse::<f64>()) {
                entities.insert(f[i].to_string(), (x, y));
            }
            i += 31;
        }
        rows.insert((t / step).round() as u64, entities);
    }
    Log { rows }
}

/// Runs esmini on `xosc`: the log, or why it did not run cleanly (exit status, error lines).
pub(crate) fn run_esmini(esmini: &Path, xosc: &Path, step: f64, extra: &[&str]) -> (Option<Log>, Vec<String>) {
    let csv = xosc.with_extension(if extra.is_empty() { "csv" } else { "nofilter.csv" });
    let log = xosc.with_extension(if extra.is_empty() { "log" } else { "nofilter.log" });
    let child = testkit::esmini_command(esmini, step, xosc).arg("--csv_logger").arg(&csv).arg("--logfile_path").arg(&log).args(extra).spawn();
    let Ok(mut child) = child else { return (None, vec!["esmini does not start".into()]) };
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break Some(s),
            Ok(None) if start.elapsed() > RUN_LIMIT => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(20)),
            Err(_) => break None,
        }
    };
    let mut problems: Vec<String> = std::fs::read_to_string(&log).unwrap_or_default().lines().filter(|l| l.contains("[error]")).map(str::to_string).collect();
    match status {
        Some(s) if s.success() => {}
        Some(s) => problems.push(format!("esmini exits with {s}")),
        None => problems.push(format!("esmini did not finish within {} s", RUN_LIMIT.as_secs())),
    }
    let parsed = std::fs::read_to_string(&csv).ok().map(|t| parse_csv(&t, step));
    (parsed, problems)
}

/// Where the entity of an obstacle is at a state: the state's position, moved by the centre of
/// a polygon's box (the exported entity's reference point is its box centre).
fn expected(s: &State, shape: &Shape) -> (f64, f64) {
    let (cx, cy) = match shape {
        Shape::Polygon(p) => {
            let xs = p.points().iter().map(|q| q.x);
            let ys = p.points().iter().map(|q| q.y);
            let mid = |v: Vec<f64>| 0.5 * (v.iter().copied().fold(f64::INFINITY, f64::min) + v.iter().copied().fold(f64::NEG_INFINITY, f64::max));
            (mid(xs.collect()), mid(ys.collect()))
        }
        _ => (0.0, 0.0),
    };
    let (sin, cos) = s.orientation.sin_cos();
    (s.x + cos * cx - sin * cy, s.y + sin * cx + cos * cy)
}

/// Every obstacle's expected positions: (entity, step in esmini steps, x, y).
pub(crate) fn expectations(s: &Scenario, steps_per_dt: u64) -> Vec<(String, u64, f64, f64)> {
    let mut out = Vec::new();
    for o in &s.dynamic_obstacles {
        let name = format!("{}_{}", o.obstacle_type.as_str(), o.id);
        for st in std::iter::once(&o.initial_state).chain(&o.trajectory) {
            let (x, y) = expected(st, &o.shape);
            out.push((name.clone(), st.time_step * steps_per_dt, x, y));
        }
    }
    for o in &s.static_obstacles {
        let st = State { time_step: 0, x: o.x, y: o.y, orientation: o.orientation, velocity: 0.0, acceleration: 0.0, yaw_rate: 0.0 };
        let (x, y) = expected(&st, &o.shape);
        out.push((format!("{}_{}", o.obstacle_type.as_str(), o.id), 0, x, y));
    }
    out
}

/// How one scenario went.
struct Outcome {
    input: PathBuf,
    states: usize,
    worst: f64,
    missing: usize,
    problems: Vec<String>,
    /// With the trajectory filter off (only run when the default run misses).
    unfiltered: Option<(f64, usize, usize)>,
}

impl Outcome {
    fn ok(&self) -> bool {
        self.problems.is_empty() && self.missing == 0 && self.worst <= TOLERANCE
    }
}

pub(crate) fn compare(log: &Log, expect: &[(String, u64, f64, f64)]) -> (f64, usize) {
    let mut worst = 0.0f64;
    let mut missing = 0;
    for (name, k, x, y) in expect {
        match log.rows.get(k).and_then(|r| r.get(name)) {
            Some(&(ex, ey)) => worst = worst.max((ex - x).hypot(ey - y)),
            None => missing += 1,
        }
    }
    (worst, missing)
}

fn round_trip(esmini: &Path, input: &Path, exported: &Result<PathBuf, String>) -> Outcome {
    let mut out = Outcome { input: input.to_path_buf(), states: 0, worst: 0.0, missing: 0, problems: Vec::new(), unfiltered: None };
    let (xosc, source) = match exported.clone().and_then(|x| export::read_source(input).map(|s| (x, s))) {
        Ok(v) => v,
        Err(e) => {
            out.problems.push(format!("not exported: {e}"));
            return out;
        }
    };
    let dt = source.scenario.header.time_step_size;
    let step = dt / 2.0;
    let expect = expectations(&source.scenario, 2);
    out.states = expect.len();
    let (log, problems) = run_esmini(esmini, &xosc, step, &[]);
    out.problems = problems;
    let Some(log) = log else {
        out.problems.push("esmini wrote no log".into());
        return out;
    };
    (out.worst, out.missing) = compare(&log, &expect);
    if !out.ok() && out.problems.is_empty() {
        let (log, problems) = run_esmini(esmini, &xosc, step, &["--traj_filter", "0"]);
        if let Some(log) = log {
            let (w, m) = compare(&log, &expect);
            out.unfiltered = Some((w, m, problems.len()));
        }
    }
    if out.ok() {
        // the logs of a good run are not kept (hundreds of MB over the whole set)
        for ext in ["csv", "log"] {
            let _ = std::fs::remove_file(xosc.with_extension(ext));
        }
    }
    out
}

#[test]
fn every_obstacle_replays_within_10_cm_in_esmini() {
    let Some(esmini) = testkit::esmini(false) else { return };
    let inputs = acceptance_scenarios();
    if inputs.is_empty() {
        return;
    }
    let start = Instant::now();
    let root = fresh_dir("esmini-round-trip");
    let exported = export_batch(&inputs, &root, &export::ExportOptions { play_to_end: true, ..Default::default() });
    let next = AtomicUsize::new(0);
    let outcomes: Mutex<Vec<(usize, Outcome)>> = Mutex::new(Vec::new());
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).max(2);
    std::thread::scope(|scope| {
        for _ in 0..workers {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some((input, xosc)) = exported.get(i) else { break };
                let o = round_trip(&esmini, input, xosc);
                outcomes.lock().expect("outcomes").push((i, o));
            });
        }
    });
    let mut outcomes = outcomes.into_inner().expect("outcomes");
    outcomes.sort_by_key(|(i, _)| *i);
    let total = outcomes.len();
    let passed = outcomes.iter().filter(|(_, o)| o.ok()).count();
    let states: usize = outcomes.iter().map(|(_, o)| o.states).sum();
    let loaded = outcomes.iter().filter(|(_, o)| o.problems.is_empty()).count();
    let worst_ok = outcomes.iter().filter(|(_, o)| o.ok()).map(|(_, o)| o.worst).fold(0.0, f64::max);
    eprintln!(
        "esmini round trip: {total} scenarios ({states} obstacle states), esmini loads {loaded} with no error, {passed} ({:.1} %) within {TOLERANCE} m at every \
         CommonRoad time step (worst among them {worst_ok:.4} m); wall time {:.0} s",
        100.0 * passed as f64 / total as f64,
        start.elapsed().as_secs_f64()
    );
    for (_, o) in outcomes.iter().filter(|(_, o)| !o.ok()) {
        let why = match o.unfiltered {
            Some((w, 0, 0)) if w <= TOLERANCE => format!("esmini's trajectory filter: with --traj_filter 0 the worst is {w:.4} m"),
            Some((w, m, e)) => format!("with --traj_filter 0 too: worst {w:.4} m, {m} states missing, {e} errors"),
            None => "no second run".to_string(),
        };
        eprintln!("  {}: worst {:.4} m, {} of {} states missing, errors {:?}; {why}", short(&o.input), o.worst, o.missing, o.states, o.problems);
    }
    assert_eq!(loaded, total, "esmini must load every exported scenario with no error");
    assert!(passed * 100 >= 95 * total, "{passed} of {total} scenarios replay within {TOLERANCE} m; at least 95 % must");
}

/// Writes a synthetic scenario's export into `dir`: its `.xosc`.
fn write_synthetic(dir: &Path, goal: commonroad::GoalPosition, options: &export::ExportOptions) -> (PathBuf, Scenario) {
    let built = crate::synthetic::scenario(goal);
    let scenario = built.scenario.clone();
    let e = export::export(&crate::synthetic::source(built), "", options).expect("exports");
    let xosc = dir.join("synthetic.xosc");
    std::fs::write(&xosc, &e.xosc).expect("write");
    if let Some(m) = &e.map {
        std::fs::write(dir.join(&m.file_name), &m.xodr).expect("write");
    }
    (xosc, scenario)
}

#[test]
fn obstacles_are_in_esmini_exactly_while_they_exist() {
    let Some(esmini) = testkit::esmini(false) else { return };
    let dir = fresh_dir("esmini-synthetic");
    let options = export::ExportOptions { play_to_end: true, ..Default::default() };
    let (xosc, scenario) = write_synthetic(&dir, crate::synthetic::circle(60.0, 1.75, 3.0), &options);
    let (log, problems) = run_esmini(&esmini, &xosc, 0.05, &[]);
    assert!(problems.is_empty(), "{problems:?}");
    let log = log.expect("a log");
    let expect = expectations(&scenario, 2);
    let (worst, missing) = compare(&log, &expect);
    assert!(worst < 1e-6 && missing == 0, "worst {worst} m, {missing} states missing");
    // absent before the first and after the last state (the truck: steps 1..=60, the
    // pedestrian: 5..=40), at every CommonRoad step of the run
    for (name, from, to) in [("truck_5", 1, 60), ("pedestrian_6", 5, 40)] {
        for k in 0..=100u64 {
            let present = log.rows.get(&(2 * k)).is_some_and(|r| r.contains_key(name));
            assert_eq!(present, (from..=to).contains(&k), "{name} at step {k}");
        }
    }
}

#[test]
fn reaching_the_goal_ends_the_run_in_esmini() {
    let Some(esmini) = testkit::esmini(false) else { return };
    let dir = fresh_dir("esmini-goal");
    // the ego starts at x = 10 at 10 m/s in its lane: it reaches the disc of 3 m around x = 60
    // (in the goal's time [2 s, 9 s], speed and heading) at 4.7 s; the obstacles go on to 10 s
    let (xosc, _) = write_synthetic(&dir, crate::synthetic::circle(60.0, 1.75, 3.0), &export::ExportOptions::default());
    let (log, problems) = run_esmini(&esmini, &xosc, 0.05, &[]);
    assert!(problems.is_empty(), "{problems:?}");
    let last = log.expect("a log").rows.keys().copied().max().expect("rows") as f64 * 0.05;
    assert!((4.6..5.0).contains(&last), "the run ends when the goal is reached, at {last} s");
    // an outside driver: the ego waits for it; esmini loads it with no error
    let options = export::ExportOptions { ego_controller: export::EgoController::External, ..Default::default() };
    let (xosc, _) = write_synthetic(&dir, crate::synthetic::circle(60.0, 1.75, 3.0), &options);
    let (log, problems) = run_esmini(&esmini, &xosc, 0.05, &[]);
    assert!(problems.is_empty(), "{problems:?}");
    let last = log.expect("a log").rows.keys().copied().max().expect("rows") as f64 * 0.05;
    assert!((last - 10.0).abs() < 0.06, "nobody drives the ego: the run ends by time, at {last} s");
}

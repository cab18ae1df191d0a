//! Forward again (issue 24): `convert(export(S))` gives S's obstacles — every state within
//! 0.01 m, matched by name (`<type>_<id>`); esmini's filter of close trajectory vertices, which
//! the engine reproduces, is foreseen by the export — and S's planning problems (their values to the
//! carrier's 6 decimals; goal lanelets, which the map round trip renumbers, as lanelets of the
//! converted map inside S's goal lanelets). On every scenario of both acceptance sets that has
//! something to convert (a scenario with neither planning problem nor obstacle has no ego and
//! no CommonRoad file to give). Exported with `--play-to-end`: by default the run ends when
//! the ego (keeping its lane and speed) reaches its goal, which can be before the last states.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use commonroad::{GoalPosition, LaneletNetwork, PlanningProblem, Scenario, State};

use crate::common::{acceptance_scenarios, export_batch, fresh_dir, short};

const POSITION: f64 = 0.01;
/// The carrier writes 6 decimals (0.5e-6 of rounding).
const VALUE: f64 = 1e-6;

fn states(o: &commonroad::DynamicObstacle) -> impl Iterator<Item = &State> {
    std::iter::once(&o.initial_state).chain(&o.trajectory)
}

/// What `convert` gives for each entity name: its states by time step.
fn forward_states(model: &convert::Model) -> HashMap<String, HashMap<u64, (f64, f64)>> {
    let name_of: HashMap<u64, &str> = model.names.iter().map(|(id, n)| (*id, n.as_str())).collect();
    let mut out: HashMap<String, HashMap<u64, (f64, f64)>> = HashMap::new();
    for o in &model.scenario.dynamic_obstacles {
        let Some(name) = name_of.get(&o.id.get()) else { continue };
        let e = out.entry(name.to_string()).or_default();
        for s in states(o) {
            e.insert(s.time_step, (s.x, s.y));
        }
    }
    for o in &model.scenario.static_obstacles {
        if let Some(name) = name_of.get(&o.id.get()) {
            out.entry(name.to_string()).or_default().insert(0, (o.x, o.y));
        }
    }
    out
}

fn near(a: f64, b: f64) -> bool {
    (a - b).abs() <= VALUE
}

/// Whether a goal lanelet `id` of the converted network lies in one of S's goal lanelets.
fn lanelet_inside(net: &LaneletNetwork, id: commonroad::LaneletId, originals: &[&commonroad::Lanelet]) -> bool {
    let Some(l) = net.lanelets.iter().find(|l| l.id == id) else { return false };
    let n = l.bounds.len();
    let mid = |i: usize| (0.5 * (l.bounds.left()[i].x + l.bounds.right()[i].x), 0.5 * (l.bounds.left()[i].y + l.bounds.right()[i].y));
    // half way between the middle vertices (n ≥ 2): never an end point, which may lie on S's
    // outline (a straight lanelet the map round trip gives with two points)
    let (a, b) = (mid(n.saturating_sub(1) / 2), mid(n / 2));
    let p = (0.5 * (a.0 + b.0), 0.5 * (a.1 + b.1));
    originals.iter().any(|o| {
        let ring: Vec<(f64, f64)> = o.bounds.right().iter().chain(o.bounds.left().iter().rev()).map(|q| (q.x, q.y)).collect();
        let mut inside = false;
        for i in 0..ring.len() {
            let (a, b) = (ring[i], ring[(i + ring.len() - 1) % ring.len()]);
            if (a.1 > p.1) != (b.1 > p.1) && p.0 < (b.0 - a.0) * (p.1 - a.1) / (b.1 - a.1) + a.0 {
                inside = !inside;
            }
        }
        inside
    })
}

/// The differences between S's planning problem and the one `convert` gives.
fn problem_differences(s: &PlanningProblem, net_s: &LaneletNetwork, f: &PlanningProblem, net_f: &LaneletNetwork) -> Vec<String> {
    let mut d = Vec::new();
    let (a, b) = (&s.initial_state, &f.initial_state);
    let pairs = [
        ("x", a.x, b.x),
        ("y", a.y, b.y),
        ("orientation", a.orientation, b.orientation),
        ("velocity", a.velocity, b.velocity),
        ("yaw rate", a.yaw_rate, b.yaw_rate),
        ("slip angle", a.slip_angle, b.slip_angle),
    ];
    for (what, p, q) in pairs {
        if !near(p, q) {
            d.push(format!("initial {what} {p} → {q}"));
        }
    }
    if a.acceleration.is_some() != b.acceleration.is_some() || !near(a.acceleration.unwrap_or(0.0), b.acceleration.unwrap_or(0.0)) {
        d.push(format!("initial acceleration {:?} → {:?}", a.acceleration, b.acceleration));
    }
    if s.goal_states.len() != f.goal_states.len() {
        d.push(format!("{} goal states → {}", s.goal_states.len(), f.goal_states.len()));
        return d;
    }
    for (i, (g, h)) in s.goal_states.iter().zip(&f.goal_states).enumerate() {
        if g.time != h.time {
            d.push(format!("goal {i} time {:?} → {:?}", g.time, h.time));
        }
        let interval = |x: &Option<commonroad::Interval>, y: &Option<commonroad::Interval>| match (x, y) {
            (None, None) => true,
            (Some(x), Some(y)) => near(x.start(), y.start()) && near(x.end(), y.end()),
            _ => false,
        };
        if !interval(&g.velocity, &h.velocity) || !interval(&g.orientation, &h.orientation) {
            d.push(format!("goal {i} velocity/orientation {:?} {:?} → {:?} {:?}", g.velocity, g.orientation, h.velocity, h.orientation));
        }
        let same_position = match (&g.position, &h.position) {
            (None, None) => true,
            (Some(GoalPosition::Lanelets(x)), Some(GoalPosition::Lanelets(y))) => {
                let originals: Vec<&commonroad::Lanelet> = net_s.lanelets.iter().filter(|l| x.contains(&l.id)).collect();
                !y.is_empty() && y.iter().all(|id| lanelet_inside(net_f, *id, &originals))
            }
            (Some(GoalPosition::Rectangles(x)), Some(GoalPosition::Rectangles(y))) => {
                x.len() == y.len()
                    && x.iter().zip(y).all(|(p, q)| {
                        near(p.center.x, q.center.x)
                            && near(p.center.y, q.center.y)
                            && near(p.orientation, q.orientation)
                            && near(p.rectangle.length(), q.rectangle.length())
                            && near(p.rectangle.width(), q.rectangle.width())
                    })
            }
            (Some(GoalPosition::Circles(x)), Some(GoalPosition::Circles(y))) => {
                x.len() == y.len()
                    && x.iter().zip(y).all(|(p, q)| near(p.center.x, q.center.x) && near(p.center.y, q.center.y) && near(p.circle.radius(), q.circle.radius()))
            }
            (Some(GoalPosition::Polygons(x)), Some(GoalPosition::Polygons(y))) => {
                x.len() == y.len()
                    && x.iter()
                        .zip(y)
                        .all(|(p, q)| p.points().len() == q.points().len() && p.points().iter().zip(q.points()).all(|(u, v)| near(u.x, v.x) && near(u.y, v.y)))
            }
            _ => false,
        };
        if !same_position {
            d.push(format!("goal {i} position {:?} → {:?}", g.position, h.position));
        }
    }
    d
}

/// The differences between S and convert(export(S)), or why there is nothing to compare.
fn forward(input: &Path, exported: &Result<PathBuf, String>) -> Result<Vec<String>, String> {
    let source = export::read_source(input)?;
    let s: &Scenario = &source.scenario;
    if source.problems.problems.is_empty() && s.dynamic_obstacles.is_empty() && s.static_obstacles.is_empty() {
        return Err("nothing to convert (no planning problem, no obstacle)".into());
    }
    let xosc = exported.clone()?;
    let name = export::scenario_name(input);
    let request = convert::Request { source: "export round trip".into(), ..convert::Request::named(&xosc, &name) }.keeping_model();
    let options = convert::ConvertOptions { dt: s.header.time_step_size, ..Default::default() };
    let (conversion, model) = convert::convert(&request, &options);
    if let Err(f) = conversion.result {
        return Ok(vec![format!("convert fails: {}", f.message)]);
    }
    let model = model.ok_or("no model kept")?;
    let got = forward_states(&model);
    let mut d = Vec::new();
    for o in &s.dynamic_obstacles {
        let name = format!("{}_{}", o.obstacle_type.as_str(), o.id);
        let Some(g) = got.get(&name) else {
            d.push(format!("{name}: not in the converted scenario"));
            continue;
        };
        let mut worst = 0.0f64;
        let mut missing = 0;
        for st in states(o) {
            match g.get(&st.time_step) {
                Some(&(x, y)) => worst = worst.max((x - st.x).hypot(y - st.y)),
                None => missing += 1,
            }
        }
        // and no state at a step S's obstacle does not have
        let extra = g.keys().filter(|k| !states(o).any(|st| st.time_step == **k)).count();
        if worst > POSITION || missing > 0 || extra > 0 {
            d.push(format!("{name}: worst {worst:.4} m, {missing} states missing, {extra} extra"));
        }
    }
    for o in &s.static_obstacles {
        let name = format!("{}_{}", o.obstacle_type.as_str(), o.id);
        let at0 = got.get(&name).and_then(|g| g.get(&0));
        // a polygon comes back as its box: its centre is compared in the esmini test
        let polygon = matches!(o.shape, commonroad::Shape::Polygon(_));
        match at0 {
            Some(&(x, y)) if polygon || (x - o.x).hypot(y - o.y) <= POSITION => {}
            other => d.push(format!("{name}: static at ({}, {}) → {other:?}", o.x, o.y)),
        }
    }
    let fp = &model.problems.problems;
    if !source.problems.problems.is_empty() {
        if fp.len() != source.problems.problems.len() {
            d.push(format!("{} planning problems → {}", source.problems.problems.len(), fp.len()));
        } else {
            for (p, q) in source.problems.problems.iter().zip(fp) {
                d.extend(problem_differences(p, &s.network, q, &model.scenario.network).into_iter().map(|x| format!("planning problem {}: {x}", p.id)));
            }
        }
    }
    Ok(d)
}

#[test]
fn convert_of_export_gives_the_obstacles_and_planning_problems_back() {
    let inputs = acceptance_scenarios();
    if inputs.is_empty() {
        return;
    }
    let root = fresh_dir("forward-again");
    let exported = export_batch(&inputs, &root, &export::ExportOptions { play_to_end: true, ..Default::default() });
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for _ in 0..std::thread::available_parallelism().map_or(2, |n| n.get()).max(2) {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some((input, xosc)) = exported.get(i) else { break };
                let r = forward(input, xosc);
                results.lock().expect("results").push((i, r));
            });
        }
    });
    let mut results = results.into_inner().expect("results");
    results.sort_by_key(|(i, _)| *i);
    let mut compared = 0;
    let mut skipped = Vec::new();
    let mut failed = Vec::new();
    for (i, r) in results {
        let input = &exported[i].0;
        match r {
            Ok(d) if d.is_empty() => compared += 1,
            Ok(d) => {
                compared += 1;
                failed.push(format!("{}: {}", short(input), d.iter().take(4).cloned().collect::<Vec<_>>().join("; ")));
            }
            Err(why) => skipped.push(format!("{}: {why}", short(input))),
        }
    }
    eprintln!("forward again: {compared} scenarios compared, {} equal, {} differ; {} not comparable", compared - failed.len(), failed.len(), skipped.len());
    for s in &skipped {
        eprintln!("  skipped {s}");
    }
    assert!(failed.is_empty(), "convert(export(S)) differs from S in {} of {compared}:\n{}", failed.len(), failed.join("\n"));
}

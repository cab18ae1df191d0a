//! The trace is audited before anything is written: a value that is not finite stops the
//! conversion; a jump between two steps that no position-setting action explains, and an
//! entity far outside the map, are said once per entity with the time and the actions then
//! running. Whatever the engine got wrong, the file does not silently carry it.

use std::collections::{BTreeMap, BTreeSet};

use commonroad::LaneletNetwork;
use engine::{EntityTrace, Trace};
use openscenario::{ActionKind, GlobalAction, PrivateAction, Scenario};

/// A jump is a step longer than the speed explains by this factor plus [`JUMP_SLACK`].
const JUMP_FACTOR: f64 = 2.0;
/// Metres a step may exceed the speed's distance by (turning the reference point, rounding).
const JUMP_SLACK: f64 = 0.5;
/// "Far outside the map": this far beyond the box around every lanelet, m, or the box's own
/// size when that is larger.
const FAR_OUTSIDE: f64 = 1000.0;

/// What the audit found: `Err` holds the message of a value that is not finite.
pub fn audit(trace: &Trace, scenario: &Scenario, map: Option<&LaneletNetwork>) -> Result<Vec<String>, String> {
    non_finite(trace)?;
    let actions = ActionIndex::new(scenario, trace);
    let mut out = jumps(trace, &actions);
    if let Some(b) = map.and_then(extent) {
        out.extend(far_outside(trace, b, &actions));
    }
    Ok(out)
}

fn non_finite(trace: &Trace) -> Result<(), String> {
    for e in &trace.entities {
        for (k, s) in e.samples.iter().enumerate() {
            let Some(s) = s else { continue };
            for (what, v) in
                [("x", s.x), ("y", s.y), ("z", s.z), ("heading", s.h), ("speed", s.speed), ("acceleration", s.acceleration), ("yaw rate", s.yaw_rate)]
            {
                if !v.is_finite() {
                    return Err(format!(
                        "the run gave entity `{}` a {what} of {v} at {:.2} s; nothing is written (an engine fault: please report the scenario)",
                        e.name,
                        trace.time(k)
                    ));
                }
            }
        }
    }
    Ok(())
}

/// Which storyboard actions set positions, which act on which entity, and when each ran (from
/// the run's event log).
struct ActionIndex<'a> {
    /// action name → (element name, entities it acts on)
    kinds: BTreeMap<&'a str, (&'a str, Vec<&'a str>)>,
    /// Times at which a position-setting action started, per entity.
    relocations: BTreeMap<&'a str, Vec<f64>>,
    /// action name → [start, end) intervals.
    running: BTreeMap<&'a str, Vec<(f64, f64)>>,
    step: f64,
}

/// Actions after which an entity may be anywhere.
fn sets_position(kind: &ActionKind) -> bool {
    matches!(
        kind,
        ActionKind::Private(PrivateAction::Teleport(_) | PrivateAction::FollowTrajectory { .. }) | ActionKind::Global(GlobalAction::AddEntity { .. })
    )
}

impl<'a> ActionIndex<'a> {
    fn new(scenario: &'a Scenario, trace: &'a Trace) -> Self {
        let mut kinds: BTreeMap<&str, (&str, Vec<&str>)> = BTreeMap::new();
        let mut setters = BTreeSet::new();
        openscenario::references::for_each_action(scenario, |a, actors| {
            let mut on: Vec<&str> = actors.to_vec();
            if let ActionKind::Global(GlobalAction::AddEntity { entity, .. }) = &a.kind {
                on.push(entity);
            }
            if sets_position(&a.kind) {
                setters.insert(a.name.as_str());
            }
            kinds.entry(a.name.as_str()).or_insert((a.kind.element_name(), Vec::new())).1.extend(on);
        });
        let mut relocations: BTreeMap<&str, Vec<f64>> = BTreeMap::new();
        let mut running: BTreeMap<&str, Vec<(f64, f64)>> = BTreeMap::new();
        for ev in &trace.events {
            let name = ev.element.as_str();
            // Init actions are logged as "Init <entity> <Element>"
            if let Some(rest) = name.strip_prefix("Init ") {
                if let Some((entity, element)) = rest.rsplit_once(' ') {
                    if ev.transition == "start" && matches!(element, "TeleportAction" | "FollowTrajectoryAction") {
                        if let Some(e) = trace.entities.iter().find(|e| e.name == entity) {
                            relocations.entry(e.name.as_str()).or_default().push(ev.time);
                        }
                    }
                }
                continue;
            }
            let Some((_, on)) = kinds.get(name) else { continue };
            match ev.transition.as_str() {
                "start" => {
                    running.entry(name).or_default().push((ev.time, f64::INFINITY));
                    if setters.contains(name) {
                        for e in on {
                            relocations.entry(e).or_default().push(ev.time);
                        }
                    }
                }
                "end" | "stop" | "skip" => {
                    if let Some(last) = running.get_mut(name).and_then(|v| v.last_mut()) {
                        if last.1.is_infinite() {
                            last.1 = ev.time;
                        }
                    }
                }
                _ => {}
            }
        }
        ActionIndex { kinds, relocations, running, step: trace.step }
    }

    /// A position-setting action for `entity` started within a step of `[t0, t1]`.
    fn explains(&self, entity: &str, t0: f64, t1: f64) -> bool {
        let slack = self.step * 1.5;
        self.relocations.get(entity).is_some_and(|ts| ts.iter().any(|&t| t >= t0 - slack && t <= t1 + slack))
    }

    /// The actions acting on `entity` that were running at `t`, as "name (Element)".
    fn in_force(&self, entity: &str, t: f64) -> String {
        let slack = self.step * 1.5;
        let list: Vec<String> = self
            .running
            .iter()
            .filter(|(name, spans)| {
                self.kinds.get(*name).is_some_and(|(_, on)| on.contains(&entity)) && spans.iter().any(|&(a, b)| a - slack <= t && t <= b + slack)
            })
            .map(|(name, _)| format!("`{name}` ({})", self.kinds.get(name).map_or("", |k| k.0)))
            .collect();
        if list.is_empty() {
            "no storyboard action was running on it (its controller moved it)".to_string()
        } else {
            format!("running: {}", list.join(", "))
        }
    }
}

/// For every entity of `trace` but the ghosts, the largest `measure` of its steps (at the first
/// step it is reached) and how many steps have one (`None`: the step is fine), said by `say`.
fn worst_steps(trace: &Trace, measure: impl Fn(&EntityTrace, usize) -> Option<f64>, say: impl Fn(&EntityTrace, f64, usize, usize) -> String) -> Vec<String> {
    let mut out = Vec::new();
    for e in trace.entities.iter().filter(|e| !trace.ghosts.contains(&e.name)) {
        let mut worst: Option<(f64, usize)> = None;
        let mut count = 0;
        for k in 0..e.samples.len() {
            let Some(d) = measure(e, k) else { continue };
            count += 1;
            if worst.is_none_or(|(w, _)| d > w) {
                worst = Some((d, k));
            }
        }
        if let Some((d, k)) = worst {
            out.push(say(e, d, k, count));
        }
    }
    out
}

/// The largest unexplained jump of each entity, said once.
fn jumps(trace: &Trace, actions: &ActionIndex<'_>) -> Vec<String> {
    let dt = trace.step;
    let jump = |e: &EntityTrace, k: usize| {
        let (Some(a), Some(b)) = (e.samples[k.checked_sub(1)?], e.samples[k]) else { return None };
        let d = (b.x - a.x).hypot(b.y - a.y);
        let allowed = JUMP_FACTOR * a.speed.abs().max(b.speed.abs()) * dt + JUMP_SLACK;
        (d > allowed && !actions.explains(&e.name, trace.time(k - 1), trace.time(k))).then_some(d)
    };
    worst_steps(trace, jump, |e, d, k, count| {
        let t = trace.time(k);
        format!(
            "entity `{}` jumps {d:.2} m between {:.2} s and {t:.2} s, more than its speed explains and with no teleport or other position-setting action{}; {}",
            e.name,
            trace.time(k - 1),
            if count > 1 { format!(" ({count} such steps; the largest is given)") } else { String::new() },
            actions.in_force(&e.name, t)
        )
    })
}

/// (min x, min y, max x, max y) of every lanelet bound point.
fn extent(map: &LaneletNetwork) -> Option<(f64, f64, f64, f64)> {
    let mut b: Option<(f64, f64, f64, f64)> = None;
    for l in &map.lanelets {
        for p in l.bounds.left().iter().chain(l.bounds.right()) {
            b = Some(match b {
                None => (p.x, p.y, p.x, p.y),
                Some((x0, y0, x1, y1)) => (x0.min(p.x), y0.min(p.y), x1.max(p.x), y1.max(p.y)),
            });
        }
    }
    b
}

/// The farthest point of each entity off the map, at the first time it is reached.
fn far_outside(trace: &Trace, (x0, y0, x1, y1): (f64, f64, f64, f64), actions: &ActionIndex<'_>) -> Vec<String> {
    let margin = FAR_OUTSIDE.max((x1 - x0).max(y1 - y0));
    let outside = |e: &EntityTrace, k: usize| {
        let s = e.samples[k].as_ref()?;
        Some((x0 - s.x).max(s.x - x1).max(y0 - s.y).max(s.y - y1)).filter(|&d| d > margin)
    };
    worst_steps(trace, outside, |e, d, k, _| {
        let t = trace.time(k);
        format!("entity `{}` is {d:.0} m outside the map at {t:.2} s (more than {margin:.0} m beyond every lanelet); {}", e.name, actions.in_force(&e.name, t))
    })
}

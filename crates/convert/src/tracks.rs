//! From the engine's trace to one track per entity: its Table I type, its shape, and its
//! states at CommonRoad time steps (bounding-box centre, wrapped heading, velocity,
//! acceleration, yaw rate) — or, for a miscellaneous object that never moves, one fixed pose.
//! Which CommonRoad element each track becomes is decided in `obstacles`.

use std::collections::BTreeMap;

use commonroad::{Shape, State};
use engine::Trace;
use openscenario::{Entity, EntityObject, Trailer};

use crate::bbox::box_center;
use crate::obstacle_type::{cr_type, CrType};
use crate::resample::{resample, Pose};

/// Boxes thinner than this (a line painted on the road, a zero-width barrier) are widened to
/// it: CommonRoad shapes must have positive size.
pub const MIN_BOX_SIDE: f64 = 0.1;

/// Depth limit when looking for inline trailer entities (hostile input).
const MAX_TRAILER_DEPTH: usize = 8;

/// One entity, converted.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    pub entity: String,
    pub cr_type: CrType,
    /// In the obstacle's frame: a `length × width` rectangle, or a circle for pedestrians.
    pub shape: Shape,
    /// Box length and width (after widening), for placed shapes.
    pub length: f64,
    pub width: f64,
    pub placement: Placement,
}

/// Where a track is over time.
#[derive(Debug, Clone, PartialEq)]
pub enum Placement {
    /// A miscellaneous object present at every step that never moves (bounding-box centre).
    /// `last_step` is the run's last CommonRoad time step (a planning problem may start at it).
    Fixed { x: f64, y: f64, orientation: f64, last_step: u64 },
    /// Runs of consecutive time steps during which the entity exists. Each run holds at least
    /// two states (`t0`, `t0+1`, …); an entity that exists for one step is padded with a copy.
    Moving(Vec<Vec<State>>),
}

/// The tracks of every entity in the trace, in trace order, plus warnings.
pub fn tracks(trace: &Trace, entities: &[Entity], dt: f64) -> (Vec<Track>, Vec<String>) {
    let mut by_name = BTreeMap::new();
    for e in entities {
        collect(e, &mut by_name, 0);
    }
    let mut out = Vec::new();
    let mut warnings = Vec::new();
    for et in &trace.entities {
        let Some(entity) = by_name.get(et.name.as_str()) else {
            if trace.ghosts.iter().any(|g| g == &et.name) {
                warnings.push(format!(
                    "entity {:?} is the ghost a FollowGhost/FollowReference controller drives ahead of its entity, not a road user: left out",
                    et.name
                ));
                continue;
            }
            warnings.push(format!("entity {:?} of the trace is not declared in the scenario: left out", et.name));
            continue;
        };
        let Some(bb) = entity.object.bounding_box() else {
            warnings.push(format!("entity {:?} is an external object reference without bounding box: left out", et.name));
            continue;
        };
        let t = cr_type(&entity.object);
        let (length, width) = (side(bb.length), side(bb.width));
        if length != bb.length || width != bb.width {
            warnings.push(format!(
                "entity {:?}: bounding box {} × {} m widened to {length} × {width} m (CommonRoad shapes need a positive size)",
                et.name, bb.length, bb.width
            ));
        }
        let shape = match t {
            // a circle that covers the whole box
            CrType::Pedestrian => Shape::circle(0.5 * length.hypot(width)),
            _ => Shape::rectangle(length, width),
        };
        let Ok(shape) = shape else {
            warnings.push(format!("entity {:?}: no valid shape: left out", et.name));
            continue;
        };
        // CommonRoad time 0 is the scenario's time 0, after any ghost's head start
        let from_zero = et.samples.get(trace.zero_index()..).unwrap_or_default();
        let poses = resample(from_zero, trace.step, dt);
        let state = |n: usize, p: &Pose| {
            let (x, y) = box_center(p.x, p.y, p.h, bb.center.x, bb.center.y);
            State { time_step: n as u64, x, y, orientation: p.h, velocity: p.speed, acceleration: p.acceleration, yaw_rate: p.yaw_rate }
        };
        let states: Vec<Option<State>> = poses.iter().enumerate().map(|(n, p)| p.as_ref().map(|p| state(n, p))).collect();
        let placement = match fixed(&entity.object, &states) {
            Some(s) => Placement::Fixed { x: s.x, y: s.y, orientation: s.orientation, last_step: states.len().saturating_sub(1) as u64 },
            None => {
                let runs = runs(&states);
                if runs.is_empty() {
                    warnings.push(format!("entity {:?} exists at no CommonRoad time step: left out", et.name));
                    continue;
                }
                if runs.len() > 1 {
                    warnings.push(format!("entity {:?} disappears and reappears: written as {} obstacles, one per appearance", et.name, runs.len()));
                }
                Placement::Moving(runs)
            }
        };
        out.push(Track { entity: et.name.clone(), cr_type: t, shape, length, width, placement });
    }
    (out, warnings)
}

fn side(v: f64) -> f64 {
    if v.is_finite() && v >= MIN_BOX_SIDE {
        v
    } else {
        MIN_BOX_SIDE
    }
}

/// Scenario entities and inline trailer entities by name.
fn collect<'a>(e: &'a Entity, map: &mut BTreeMap<String, &'a Entity>, depth: usize) {
    collect_as(e.name.clone(), e, map, depth);
}

/// An inline trailer is the run entity `<tow>+` (the engine names it as esmini does, after its
/// tow vehicle: `Truck+`, then `Truck++` for the trailer of that trailer), not the name written
/// inside the vehicle model, which a catalog repeats for every truck that uses it.
fn collect_as<'a>(key: String, e: &'a Entity, map: &mut BTreeMap<String, &'a Entity>, depth: usize) {
    let trailer_key = format!("{key}+");
    map.entry(key).or_insert(e);
    if depth >= MAX_TRAILER_DEPTH {
        return;
    }
    if let EntityObject::Vehicle(v) = &e.object {
        if let Some(Trailer::Entity(t)) = &v.trailer {
            collect_as(trailer_key, t, map, depth + 1);
        }
    }
}

/// Tolerances for "never moves".
const FIXED_POS_EPS: f64 = 1e-6;
const FIXED_ANGLE_EPS: f64 = 1e-9;

/// A misc object present at every step whose pose never changes: its pose.
fn fixed(object: &EntityObject, states: &[Option<State>]) -> Option<State> {
    if CrType::always_dynamic(object) {
        return None;
    }
    let first = (*states.first()?)?;
    states
        .iter()
        .all(|s| {
            s.is_some_and(|s| {
                (s.x - first.x).abs() <= FIXED_POS_EPS && (s.y - first.y).abs() <= FIXED_POS_EPS && (s.orientation - first.orientation).abs() <= FIXED_ANGLE_EPS
            })
        })
        .then_some(first)
}

/// Maximal runs of consecutive present states; a one-state run gets a copy one step later
/// (a trajectory needs at least one state after the initial one).
fn runs(states: &[Option<State>]) -> Vec<Vec<State>> {
    let mut out: Vec<Vec<State>> = Vec::new();
    let mut current: Vec<State> = Vec::new();
    for s in states {
        match s {
            Some(s) => current.push(*s),
            None if !current.is_empty() => out.push(std::mem::take(&mut current)),
            None => {}
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    for run in &mut out {
        if let [only] = run.as_slice() {
            let pad = State { time_step: only.time_step + 1, ..*only };
            run.push(pad);
        }
    }
    out
}

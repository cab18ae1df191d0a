//! OpenDRIVE signals → CommonRoad traffic signs, traffic lights and stop lines, each
//! referenced by the lanelets it is valid for (its `validity` lanes, else the lanes whose
//! driving direction matches its orientation; lanes for motor vehicles first).
//! `signalReference`s add the referencing road's lanelets to the referenced signal.

pub mod sign_map;

use crate::borders::border_idx;
use crate::build::Built;
use crate::options::MapOptions;
use crate::sampling::station;
use crate::warn::WarningSink;
use commonroad::{CycleElement, IdAllocator, LineMarking, Point, StopLine, TrafficLight, TrafficLightColor, TrafficLightId, TrafficSign, TrafficSignId};
use opendrive::{LaneRef, LaneValidity, RoadNetwork, Signal, SignalOrientation};
use sign_map::{map_sign, SignKind};
use std::collections::BTreeMap;
use std::num::NonZeroU64;

/// What a signal becomes.
#[derive(Debug, Clone, PartialEq)]
enum Role {
    Sign(commonroad::TrafficSignElement),
    Light,
    StopLine,
    Dropped(String),
}

/// Pedestrian (and pedestrian + bicycle) lights of the OpenDRIVE catalogue: they control a
/// crossing, not the lanes a CommonRoad `trafficLightRef` would stop.
const PEDESTRIAN_LIGHTS: [u64; 2] = [1_000_002, 1_000_007];

/// Whether a signal is a traffic light for vehicles: dynamic, of the 1000001… family of
/// light types, not a pedestrian light.
pub fn is_light(sig: &Signal) -> bool {
    let n: Option<u64> = sig.type_raw.trim().parse().ok();
    sig.dynamic && n.is_some_and(|n| (1_000_001..=1_000_099).contains(&n) && !PEDESTRIAN_LIGHTS.contains(&n))
}

fn role(sig: &Signal, default_country: &str) -> Role {
    let t = sig.type_raw.trim();
    if t == "294" {
        return Role::StopLine;
    }
    if is_light(sig) {
        return Role::Light;
    }
    if sig.dynamic && sig.type_raw.trim().parse::<u64>().is_ok_and(|n| PEDESTRIAN_LIGHTS.contains(&n)) {
        return Role::Dropped("pedestrian light: CommonRoad lights control vehicle lanelets".into());
    }
    if sig.dynamic {
        return Role::Dropped(format!("dynamic signal of type `{t}` is neither a sign nor a known light type"));
    }
    let country = sig.country.as_deref().filter(|c| !c.trim().is_empty()).unwrap_or(default_country);
    match map_sign(country, t, sig.subtype.as_deref(), sig.value, sig.unit.as_deref()) {
        SignKind::Sign(e) => Role::Sign(e),
        SignKind::Dropped(why) => Role::Dropped(why),
    }
}

/// Lanelets (indices) on road `ri` at `s` that a signal with `orientation`/`validity` is for.
fn valid_lanelets(net: &RoadNetwork, built: &Built, ri: usize, s: f64, orientation: SignalOrientation, validity: &[LaneValidity]) -> Vec<usize> {
    let Some(road) = net.roads.get(ri) else { return Vec::new() };
    let si = road.section_index_at(s.clamp(0.0, road.length));
    let Some(sec) = road.lane_sections.get(si) else { return Vec::new() };
    // validity naming only the centre lane (e.g. a crosswalk's lights) counts as none
    let validity_lanes = validity.iter().any(|v| v.from_lane != 0 || v.to_lane != 0);
    let mut cands: Vec<usize> = Vec::new();
    for lane in sec.left.iter().chain(&sec.right) {
        let Some(&i) = built.index_of.get(&LaneRef { road: ri, section: si, lane: lane.id }) else { continue };
        let Some(o) = built.origins.get(i) else { continue };
        let ok = if !validity_lanes {
            match orientation {
                SignalOrientation::Plus => o.along_s,
                SignalOrientation::Minus => !o.along_s,
                SignalOrientation::Both => true,
            }
        } else {
            validity.iter().any(|v| lane.id >= v.from_lane.min(v.to_lane) && lane.id <= v.from_lane.max(v.to_lane))
        };
        if ok {
            cands.push(i);
        }
    }
    if validity_lanes {
        // the file names the lanes: take them as they are
        return cands;
    }
    let vehicular: Vec<usize> = cands.iter().copied().filter(|&i| built.classes.get(i).is_some_and(|c| c.vehicular)).collect();
    if vehicular.is_empty() {
        cands
    } else {
        vehicular
    }
}

/// Left and right point of lanelet `i`'s cross-section at road s `s`.
fn cross_section(net: &RoadNetwork, built: &Built, i: usize, s: f64) -> Option<[Point; 2]> {
    let o = built.origins.get(i)?;
    let road = net.roads.get(o.lane.road)?;
    let sec = road.lane_sections.get(o.lane.section)?;
    let (left_side, pos) = match sec.left.iter().position(|l| l.id == o.lane.lane) {
        Some(p) => (true, p),
        None => (false, sec.right.iter().position(|l| l.id == o.lane.lane)?),
    };
    let b = border_idx(sec.left.len(), left_side, pos);
    let (a, z) = road.section_range(o.lane.section)?;
    let st = station(road, o.lane.section, s.clamp(a, z));
    let (plus, minus) = if left_side { (b.outer, b.inner) } else { (b.inner, b.outer) };
    let (l, r) = if o.along_s { (plus, minus) } else { (minus, plus) };
    let p = |k: usize| st.points.get(k).map(|q| Point::new(q.x, q.y));
    Some([p(l)?, p(r)?])
}

/// Signs, lights and stop lines of the whole network; lanelets get their references.
/// Also returns the light made of each OpenDRIVE signal id (the name an OpenSCENARIO
/// TrafficSignalStateAction uses), so that a run's signal states can become the light's cycle.
pub fn convert_signals(
    net: &RoadNetwork,
    built: &mut Built,
    opts: &MapOptions,
    ids: &mut IdAllocator,
    warn: &mut WarningSink,
) -> (Vec<TrafficSign>, Vec<TrafficLight>, BTreeMap<String, TrafficLightId>) {
    let default_country = opts.default_country.clone().unwrap_or_else(|| "DE".to_string());
    // (road, signal index) → lanelets it is valid for
    let mut targets: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
    let mut by_id: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
    for (ri, road) in net.roads.iter().enumerate() {
        for (k, sig) in road.signals.iter().enumerate() {
            by_id.entry(sig.id.as_str()).or_insert((ri, k));
            targets.insert((ri, k), valid_lanelets(net, built, ri, sig.s, sig.orientation, &sig.validity));
        }
    }
    for (ri, road) in net.roads.iter().enumerate() {
        for r in &road.signal_references {
            match by_id.get(r.id.as_str()) {
                Some(key) => {
                    let extra = valid_lanelets(net, built, ri, r.s, r.orientation, &r.validity);
                    targets.entry(*key).or_default().extend(extra);
                }
                None => warn.at(&net.file, road.pos, format!("road `{}`: signalReference to unknown signal `{}`", road.id, r.id)),
            }
        }
    }
    let mut signs = Vec::new();
    let mut lights = Vec::new();
    let mut light_of_signal = BTreeMap::new();
    let [red, red_yellow, green, yellow] = opts.light_cycle.map(|d| NonZeroU64::new(d).unwrap_or(NonZeroU64::MIN));
    for ((ri, k), mut lanelets) in targets {
        let Some(road) = net.roads.get(ri) else { continue };
        let Some(sig) = road.signals.get(k) else { continue };
        lanelets.sort_unstable();
        lanelets.dedup();
        let here = || format!("road `{}` signal `{}`", road.id, sig.id);
        let role = role(sig, &default_country);
        if let Role::Dropped(why) = &role {
            warn.at(&net.file, road.pos, format!("{}: dropped: {why}", here()));
            continue;
        }
        if lanelets.is_empty() {
            warn.at(&net.file, road.pos, format!("{}: dropped: no lanelet it is valid for", here()));
            continue;
        }
        let w = road.st_to_world(sig.s, sig.t);
        let position = Some(Point::new(w.x, w.y));
        match role {
            Role::Sign(element) => {
                let id: TrafficSignId = ids.traffic_sign();
                signs.push(TrafficSign { id, elements: vec![element], position, is_virtual: false });
                for &i in &lanelets {
                    if let Some(l) = built.lanelets.get_mut(i) {
                        l.traffic_sign_refs.push(id);
                    }
                }
            }
            Role::Light => {
                let id: TrafficLightId = ids.traffic_light();
                let cycle = vec![
                    CycleElement { duration: red, color: TrafficLightColor::Red },
                    CycleElement { duration: red_yellow, color: TrafficLightColor::RedYellow },
                    CycleElement { duration: green, color: TrafficLightColor::Green },
                    CycleElement { duration: yellow, color: TrafficLightColor::Yellow },
                ];
                lights.push(TrafficLight { id, cycle, time_offset: 0, position, direction: None, active: Some(true) });
                light_of_signal.entry(sig.id.clone()).or_insert(id);
                for &i in &lanelets {
                    if let Some(l) = built.lanelets.get_mut(i) {
                        l.traffic_light_refs.push(id);
                    }
                }
            }
            Role::StopLine => {
                for &i in &lanelets {
                    // only the stop line's own road: a reference elsewhere has its own s
                    if built.origins.get(i).is_some_and(|o| o.lane.road != ri) {
                        continue;
                    }
                    let pts = cross_section(net, built, i, sig.s);
                    if let Some(l) = built.lanelets.get_mut(i) {
                        if l.stop_line.is_none() {
                            l.stop_line =
                                Some(StopLine { points: pts, line_marking: LineMarking::Solid, traffic_sign_refs: vec![], traffic_light_refs: vec![] });
                        }
                    }
                }
            }
            Role::Dropped(_) => {}
        }
    }
    // a stop line on a lanelet with lights belongs to those lights
    for l in &mut built.lanelets {
        let refs = l.traffic_light_refs.clone();
        if let Some(sl) = l.stop_line.as_mut() {
            sl.traffic_light_refs = refs;
        }
    }
    (signs, lights, light_of_signal)
}

//! What the generator knows of a map, computed from the map itself (osc2cr's `opendrive`
//! crate): where an entity may start (driving lanes and sidewalks of roads outside junctions,
//! wide enough over a stretch of s), which way traffic flows in each, and where a lane leads —
//! a walk along the lane graph in the driving direction through sections, roads and
//! junctions, which routes, trajectories and target positions are made from.

use opendrive::{drives_along_s, ContactPoint, LaneRef, LaneType, RoadNetwork};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// A stretch of one lane where an entity may start.
#[derive(Debug, Clone, PartialEq)]
pub struct Spot {
    /// Index of the road in the network.
    pub road: usize,
    pub road_id: String,
    pub lane: i32,
    pub s_min: f64,
    pub s_max: f64,
    /// Traffic in the lane drives along +s.
    pub along_s: bool,
    /// A sidewalk (for pedestrians), not a driving lane.
    pub sidewalk: bool,
}

/// Where an entity is (or is meant to be): a lane of a road at `s`, moving along +s or not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Place {
    pub road: usize,
    pub lane: i32,
    pub s: f64,
    /// The entity's direction of travel is +s.
    pub forward: bool,
}

/// One stretch of a walk: lane `lane` of road `road` from `s_from` to `s_to` (either order:
/// the walk's direction on this road).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leg {
    pub road: usize,
    pub section: usize,
    pub lane: i32,
    pub s_from: f64,
    pub s_to: f64,
}

impl Leg {
    pub fn length(&self) -> f64 {
        (self.s_to - self.s_from).abs()
    }
    pub fn forward(&self) -> bool {
        self.s_to >= self.s_from
    }
}

/// Lane types a vehicle drives on (esmini's set of driving lanes, as the engine has it).
pub fn drivable(kind: LaneType) -> bool {
    kind.is_any_driving()
}

/// Shortest stretch of a lane section worth starting on, m.
const MIN_SPOT: f64 = 30.0;
/// Distance kept from a section's ends, m.
const MARGIN: f64 = 5.0;

/// Every spot of the network: driving lanes at least 2.5 m wide, sidewalks at least 1 m,
/// over a stretch of at least 30 m of a lane section of a road outside junctions.
pub fn spots(net: &RoadNetwork) -> Vec<Spot> {
    let mut out = Vec::new();
    for (ri, r) in net.roads.iter().enumerate() {
        if r.junction.is_some() {
            continue;
        }
        for (si, sec) in r.lane_sections.iter().enumerate() {
            let Some((a, b)) = r.section_range(si) else { continue };
            if b - a < MIN_SPOT + 2.0 * MARGIN {
                continue;
            }
            let (s_min, s_max) = (a + MARGIN, b - MARGIN);
            for lane in sec.left.iter().chain(&sec.right) {
                let sidewalk = lane.kind == LaneType::Sidewalk;
                if !(lane.kind == LaneType::Driving || sidewalk) {
                    continue;
                }
                let min_width = if sidewalk { 1.0 } else { 2.5 };
                let wide = [s_min, 0.5 * (s_min + s_max), s_max].iter().all(|&s| r.lane_borders(si, lane.id, s).is_some_and(|w| w.width().abs() >= min_width));
                if !wide {
                    continue;
                }
                out.push(Spot { road: ri, road_id: r.id.clone(), lane: lane.id, s_min, s_max, along_s: drives_along_s(r.rule, lane.id), sidewalk });
            }
        }
    }
    out
}

/// The drivable lanes of road `road` at `s` (both sides), with whether each drives along +s.
pub fn lanes_at(net: &RoadNetwork, road: usize, s: f64) -> Vec<(i32, bool)> {
    let Some(r) = net.roads.get(road) else { return Vec::new() };
    let si = r.section_index_at(s);
    let Some(sec) = r.lane_sections.get(si) else { return Vec::new() };
    sec.left
        .iter()
        .chain(&sec.right)
        .filter(|l| drivable(l.kind) && r.lane_borders(si, l.id, s).is_some_and(|w| w.width().abs() >= 2.0))
        .map(|l| (l.id, drives_along_s(r.rule, l.id)))
        .collect()
}

/// Which end of road `to` is nearer the point where the walk leaves road `from` at `end`.
fn entry_end(net: &RoadNetwork, from: usize, from_end: ContactPoint, to: usize) -> ContactPoint {
    let s_exit = match from_end {
        ContactPoint::Start => 0.0,
        ContactPoint::End => net.roads.get(from).map_or(0.0, |r| r.length),
    };
    let (Some(p), Some(r)) = (net.road_to_world(from, s_exit, 0.0), net.roads.get(to)) else { return ContactPoint::Start };
    let d = |s: f64| net.road_to_world(to, s, 0.0).map_or(f64::INFINITY, |q| (q.x - p.x).hypot(q.y - p.y));
    if d(0.0) <= d(r.length) {
        ContactPoint::Start
    } else {
        ContactPoint::End
    }
}

/// A walk of about `length` metres from `start` in its direction of travel, along the lane
/// graph (a random branch where a lane splits, as through a junction). Ends early where the
/// lane leads nowhere drivable in the travel direction.
pub fn walk(net: &RoadNetwork, start: Place, length: f64, rng: &mut ChaCha8Rng) -> Vec<Leg> {
    let mut legs = Vec::new();
    let Some(r) = net.roads.get(start.road) else { return legs };
    let mut cur = LaneRef { road: start.road, section: r.section_index_at(start.s), lane: start.lane };
    let mut s = start.s;
    let mut forward = start.forward;
    let mut left = length;
    // a hard cap on hops: a map of tiny roads must not make the walk endless
    for _ in 0..64 {
        let Some(road) = net.roads.get(cur.road) else { break };
        let Some((a, b)) = road.section_range(cur.section) else { break };
        let end_s = if forward { b } else { a };
        let span = (end_s - s).abs();
        if span >= left {
            let s_to = if forward { s + left } else { s - left };
            legs.push(Leg { road: cur.road, section: cur.section, lane: cur.lane, s_from: s, s_to });
            return legs;
        }
        legs.push(Leg { road: cur.road, section: cur.section, lane: cur.lane, s_from: s, s_to: end_s });
        left -= span;
        let end = if forward { ContactPoint::End } else { ContactPoint::Start };
        let next: Vec<LaneRef> = net
            .lanes_across(cur, end)
            .into_iter()
            .filter(|l| {
                net.roads.get(l.road).and_then(|rd| rd.lane_sections.get(l.section)).and_then(|sec| sec.lane(l.lane)).is_some_and(|ln| drivable(ln.kind))
            })
            .collect();
        if next.is_empty() {
            break;
        }
        let n = next[rng.gen_range(0..next.len())];
        let Some(nr) = net.roads.get(n.road) else { break };
        let enter = if n.road == cur.road { end.opposite() } else { entry_end(net, cur.road, end, n.road) };
        forward = enter == ContactPoint::Start;
        if drives_along_s(nr.rule, n.lane) != forward {
            break; // the lane links lead against the traffic of the next lane
        }
        s = if n.road == cur.road {
            if forward {
                b
            } else {
                a
            }
        } else if forward {
            0.0
        } else {
            nr.length
        };
        cur = n;
    }
    legs
}

/// The place `dist` metres along a walk (its end if the walk is shorter).
pub fn along(legs: &[Leg], dist: f64) -> Option<Place> {
    let mut left = dist.max(0.0);
    for leg in legs {
        if left <= leg.length() {
            let s = if leg.forward() { leg.s_from + left } else { leg.s_from - left };
            return Some(Place { road: leg.road, lane: leg.lane, s, forward: leg.forward() });
        }
        left -= leg.length();
    }
    legs.last().map(|l| Place { road: l.road, lane: l.lane, s: l.s_to, forward: l.forward() })
}

/// Total length of a walk, m.
pub fn walk_length(legs: &[Leg]) -> f64 {
    legs.iter().map(Leg::length).sum()
}

/// World pose (x, y, heading of travel) of a place, `offset` metres from the lane centre
/// towards +t.
pub fn world(net: &RoadNetwork, p: &Place, offset: f64) -> Option<(f64, f64, f64)> {
    let w = net.lane_to_world(p.road, p.lane, p.s, offset)?;
    let h = if p.forward { w.heading } else { w.heading + std::f64::consts::PI };
    Some((w.x, w.y, h))
}

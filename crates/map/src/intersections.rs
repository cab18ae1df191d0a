//! Intersections from junctions with connecting roads: one incoming per incoming road (its
//! lanelets that lead into the junction), each incoming's successors (the first junction
//! lanelets) sorted into left / straight / right by the heading change from the incoming
//! lanelet's end to the end of the path through the junction, and `isLeftOf` (the incoming
//! located to the left of this one) where an approach arrives from about 90° to the left.

use crate::build::Built;
use commonroad::{IdAllocator, Incoming, Intersection, Lanelet};
use opendrive::RoadNetwork;
use std::collections::BTreeMap;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// Heading change above which a path turns (rad; 30°).
pub const TURN_THRESHOLD: f64 = PI / 6.0;
/// How many lanelets a path through one junction may have.
const MAX_PATH: usize = 16;

/// Wraps an angle to (−π, π].
pub fn wrap(a: f64) -> f64 {
    let mut a = a % (2.0 * PI);
    if a <= -PI {
        a += 2.0 * PI;
    } else if a > PI {
        a -= 2.0 * PI;
    }
    a
}

/// Heading of the centre line at the end (`end = true`) or start of a lanelet.
pub fn lanelet_heading(l: &Lanelet, end: bool) -> f64 {
    let (lb, rb) = (l.bounds.left(), l.bounds.right());
    let c = |k: usize| match (lb.get(k), rb.get(k)) {
        (Some(a), Some(b)) => Some((0.5 * (a.x + b.x), 0.5 * (a.y + b.y))),
        _ => None,
    };
    let n = lb.len();
    let (i, j) = if end { (n.saturating_sub(2), n.saturating_sub(1)) } else { (0, 1) };
    match (c(i), c(j)) {
        (Some(a), Some(b)) => (b.1 - a.1).atan2(b.0 - a.0),
        _ => 0.0,
    }
}

/// Which way a turn goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Turn {
    Left,
    Straight,
    Right,
}

/// Left / straight / right from a heading change.
pub fn classify_turn(delta: f64) -> Turn {
    let d = wrap(delta);
    if d > TURN_THRESHOLD {
        Turn::Left
    } else if d < -TURN_THRESHOLD {
        Turn::Right
    } else {
        Turn::Straight
    }
}

pub fn intersections(net: &RoadNetwork, built: &Built, ids: &mut IdAllocator) -> Vec<Intersection> {
    let pos_of: BTreeMap<commonroad::LaneletId, usize> = built.lanelets.iter().enumerate().map(|(i, l)| (l.id, i)).collect();
    let junction_of = |i: usize| -> Option<&str> { built.origins.get(i).and_then(|o| net.roads.get(o.lane.road)).and_then(|r| r.junction.as_deref()) };
    let vehicular = |i: usize| built.classes.get(i).is_some_and(|c| c.vehicular);
    let mut out = Vec::new();
    for j in &net.junctions {
        // incoming road → (incoming lanelets, successors)
        let mut incomings: BTreeMap<usize, (Vec<usize>, Vec<usize>)> = BTreeMap::new();
        for (i, l) in built.lanelets.iter().enumerate() {
            // vehicle lanes only: sidewalks and shoulders are not what an intersection routes
            if junction_of(i).is_some() || !vehicular(i) {
                continue;
            }
            let into: Vec<usize> =
                l.successors.iter().filter_map(|s| pos_of.get(s).copied()).filter(|&k| junction_of(k) == Some(j.id.as_str()) && vehicular(k)).collect();
            if into.is_empty() {
                continue;
            }
            let Some(road) = built.origins.get(i).map(|o| o.lane.road) else { continue };
            let e = incomings.entry(road).or_default();
            e.0.push(i);
            e.1.extend(into);
        }
        if incomings.is_empty() {
            continue;
        }
        let iid = ids.intersection();
        let mut incs: Vec<(Incoming, f64)> = Vec::new();
        for (_road, (inc, mut succ)) in incomings {
            succ.sort_unstable();
            succ.dedup();
            let approach = inc.first().and_then(|&i| built.lanelets.get(i)).map_or(0.0, |l| lanelet_heading(l, true));
            let mut incoming = Incoming {
                id: ids.incoming(),
                incoming_lanelets: inc.iter().filter_map(|&i| built.lanelets.get(i)).map(|l| l.id).collect(),
                successors_right: vec![],
                successors_straight: vec![],
                successors_left: vec![],
                is_left_of: None,
            };
            for s in succ {
                let Some(first) = built.lanelets.get(s) else { continue };
                // follow the path to the last lanelet of this junction
                let mut last = first;
                for _ in 0..MAX_PATH {
                    let next = last.successors.iter().filter_map(|x| pos_of.get(x).copied()).find(|&k| junction_of(k) == Some(j.id.as_str()));
                    match next.and_then(|k| built.lanelets.get(k)) {
                        Some(n) if n.id != first.id => last = n,
                        _ => break,
                    }
                }
                let delta = lanelet_heading(last, true) - approach;
                match classify_turn(delta) {
                    Turn::Left => incoming.successors_left.push(first.id),
                    Turn::Straight => incoming.successors_straight.push(first.id),
                    Turn::Right => incoming.successors_right.push(first.id),
                }
            }
            incs.push((incoming, approach));
        }
        // the incoming on my left drives about 90° clockwise of my heading
        let headings: Vec<(commonroad::IncomingId, f64)> = incs.iter().map(|(i, h)| (i.id, *h)).collect();
        for (inc, h) in incs.iter_mut() {
            let best = headings
                .iter()
                .filter(|(id, _)| *id != inc.id)
                .map(|(id, h2)| (*id, (wrap(h2 - *h) + FRAC_PI_2).abs()))
                .filter(|(_, err)| *err < FRAC_PI_4)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            inc.is_left_of = best.map(|(id, _)| id);
        }
        out.push(Intersection { id: iid, incomings: incs.into_iter().map(|(i, _)| i).collect(), crossings: vec![] });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turns_by_heading_change() {
        assert_eq!(classify_turn(FRAC_PI_2), Turn::Left);
        assert_eq!(classify_turn(-FRAC_PI_2), Turn::Right);
        assert_eq!(classify_turn(0.2), Turn::Straight);
        // crossing ±π: from 170° to −170° is a 20° left change
        assert_eq!(classify_turn(wrap((-170f64).to_radians() - 170f64.to_radians())), Turn::Straight);
        assert!((wrap(3.0 * PI) - PI).abs() < 1e-12);
        assert!((wrap(-PI) - PI).abs() < 1e-12);
    }
}

//! Distance along the road network between two road positions: the shortest chain of linked
//! roads (through junctions), measured along the reference lines, as esmini's position delta
//! measures it road-level (either direction from the start, lanes ignored). A
//! SynchronizeAction's distances follow the lane instead (`road_path::path_ends`).

use opendrive::{ContactPoint, RoadNetwork};

/// Most road ends the search settles (hostile input: bounded work per call).
const MAX_SETTLED: usize = 512;

/// Unsigned distance along the roads from (road `a`, s `sa`) to (road `b`, s `sb`); `None` when
/// no chain of linked roads joins them.
pub(crate) fn road_distance(net: &RoadNetwork, a: usize, sa: f64, b: usize, sb: f64) -> Option<f64> {
    road_distance_within(net, a, sa, b, sb, f64::INFINITY)
}

/// [`road_distance`] when only distances up to `max` matter: `None` also when the distance
/// exceeds `max`, found without searching the roads beyond (every road end the search settles
/// before reaching `b` is no farther than the result).
pub(crate) fn road_distance_within(net: &RoadNetwork, a: usize, sa: f64, b: usize, sb: f64, max: f64) -> Option<f64> {
    if a == b {
        return Some((sb - sa).abs());
    }
    let ra = net.roads.get(a)?;
    let rb = net.roads.get(b)?;
    // Frontier of reached road ends (the far side of a link), with the distance driven so far.
    let mut frontier: Vec<(f64, usize, ContactPoint)> = Vec::new();
    let mut settled: Vec<(usize, ContactPoint)> = Vec::new();
    let push_links = |frontier: &mut Vec<(f64, usize, ContactPoint)>, road: usize, end: ContactPoint, d: f64| {
        for e in net.roads_at(road, end) {
            frontier.push((d, e.road, e.contact));
        }
    };
    push_links(&mut frontier, a, ContactPoint::Start, sa.clamp(0.0, ra.length));
    push_links(&mut frontier, a, ContactPoint::End, (ra.length - sa).max(0.0));
    while settled.len() < MAX_SETTLED {
        let k = (0..frontier.len()).min_by(|&i, &j| frontier[i].0.total_cmp(&frontier[j].0))?;
        let (d, road, entry) = frontier.swap_remove(k);
        if d > max {
            return None;
        }
        if settled.contains(&(road, entry)) {
            continue;
        }
        settled.push((road, entry));
        if road == b {
            let along = match entry {
                ContactPoint::Start => sb,
                ContactPoint::End => rb.length - sb,
            };
            return Some(d + along.max(0.0));
        }
        let Some(r) = net.roads.get(road) else { continue };
        let exit = match entry {
            ContactPoint::Start => ContactPoint::End,
            ContactPoint::End => ContactPoint::Start,
        };
        push_links(&mut frontier, road, exit, d + r.length);
    }
    None
}

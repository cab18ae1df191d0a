//! Successors and predecessors → lane links, road links and junctions.
//!
//! Every lanelet link joins the end of one lane to the start of another; where both lie in
//! one road (consecutive sections) it is a lane link. Otherwise it joins two road ends. Road
//! ends joined by links form clusters: a cluster of two road ends is a road-to-road link; a
//! larger one (a fork, a merge, a crossing) is a junction — the junction of the CommonRoad
//! intersection whose lanelets take part (default type, its lanelets' roads the connecting
//! roads), else a direct junction (OpenDRIVE 1.7's junction for forks and merges without
//! connecting roads).

use crate::model::{Connection, Junction, LinkTarget, Road};
use crate::roads::Placed;
use crate::warning::{Subject, Warning};
use commonroad::{LaneletNetwork, LaneletType};
use std::collections::{BTreeMap, BTreeSet};

/// A road end: (road index, at its start).
type End = (usize, bool);

/// A lanelet link between two lanes: from the end of `from` to the start of `to`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct LinkPair {
    from: usize,
    to: usize,
}

/// Lanelets (indices) of each CommonRoad intersection: the incomings' successors and the
/// intersection lanelets that follow them.
pub(crate) fn intersection_of(net: &LaneletNetwork) -> BTreeMap<usize, u64> {
    let pos: BTreeMap<u64, usize> = net.lanelets.iter().enumerate().map(|(i, l)| (l.id.get(), i)).collect();
    let mut out = BTreeMap::new();
    for inter in &net.intersections {
        let mut stack: Vec<usize> = inter
            .incomings
            .iter()
            .flat_map(|inc| inc.successors_right.iter().chain(&inc.successors_straight).chain(&inc.successors_left))
            .filter_map(|id| pos.get(&id.get()).copied())
            .collect();
        while let Some(i) = stack.pop() {
            if out.contains_key(&i) {
                continue;
            }
            out.insert(i, inter.id.get());
            if let Some(l) = net.lanelets.get(i) {
                for s in &l.successors {
                    if let Some(&j) = pos.get(&s.get()) {
                        if net.lanelets.get(j).is_some_and(|x| x.lanelet_types.contains(&LaneletType::Intersection)) {
                            stack.push(j);
                        }
                    }
                }
            }
        }
    }
    out
}

fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// Lane of `p` at a road end: its `predecessors` list at the start, `successors` at the end.
fn lane_list(roads: &mut [Road], p: Placed, at_start: bool) -> Option<&mut Vec<i32>> {
    let road = roads.get_mut(p.road)?;
    let sec = road.sections.get_mut(p.section)?;
    let lane = sec.left.iter_mut().chain(sec.right.iter_mut()).find(|l| l.id == p.lane)?;
    Some(if at_start { &mut lane.predecessors } else { &mut lane.successors })
}

fn push_unique(v: &mut Vec<i32>, x: i32) {
    if !v.contains(&x) {
        v.push(x);
    }
}

/// The road end where a lane is left (`leaving`) or entered, or `None` when that end is
/// inside the road (between two of its sections).
fn road_end(roads: &[Road], p: Placed, leaving: bool) -> Option<End> {
    let last = roads.get(p.road)?.sections.len().saturating_sub(1);
    // leaving along s is at the larger s
    let at_start = leaving != p.along;
    let inner = if at_start { p.section > 0 } else { p.section < last };
    (!inner).then_some((p.road, at_start))
}

/// Writes lane links, road links and junctions. `junction_ids` start at `first_junction_id`.
pub(crate) fn link(net: &LaneletNetwork, roads: &mut [Road], placed: &[Option<Placed>], first_junction_id: u64, warnings: &mut Vec<Warning>) -> Vec<Junction> {
    let pos: BTreeMap<u64, usize> = net.lanelets.iter().enumerate().map(|(i, l)| (l.id.get(), i)).collect();
    let mut pairs: BTreeSet<LinkPair> = BTreeSet::new();
    for (i, l) in net.lanelets.iter().enumerate() {
        for (list, forward) in [(&l.successors, true), (&l.predecessors, false)] {
            for other in list {
                let Some(&j) = pos.get(&other.get()) else {
                    warnings.push(Warning::new(Subject::Lanelet(l.id.get()), format!("linked lanelet {} does not exist; link dropped", other.get())));
                    continue;
                };
                if placed.get(i).copied().flatten().is_none() || placed.get(j).copied().flatten().is_none() {
                    continue;
                }
                pairs.insert(if forward { LinkPair { from: i, to: j } } else { LinkPair { from: j, to: i } });
            }
        }
    }
    let inter = intersection_of(net);
    // the CommonRoad intersection of each road (the first of its lanelets that has one)
    let mut road_inter: BTreeMap<usize, u64> = BTreeMap::new();
    for (i, p) in placed.iter().enumerate() {
        if let (Some(p), Some(&x)) = (p, inter.get(&i)) {
            road_inter.entry(p.road).or_insert(x);
        }
    }
    let node = |e: End| e.0 * 2 + usize::from(e.1);
    let mut parent: Vec<usize> = (0..roads.len() * 2).collect();
    // (pair, from end, to end) of links between road ends
    let mut across: Vec<(LinkPair, End, End)> = Vec::new();
    for pair in &pairs {
        let (Some(a), Some(b)) = (placed[pair.from], placed[pair.to]) else { continue };
        match (road_end(roads, a, true), road_end(roads, b, false)) {
            (Some(ea), Some(eb)) => {
                let (x, y) = (find(&mut parent, node(ea)), find(&mut parent, node(eb)));
                parent[x] = y;
                across.push((*pair, ea, eb));
            }
            (None, None) if a.road == b.road => {
                // consecutive sections of one road
                let at_start_a = !a.along;
                if let Some(v) = lane_list(roads, a, at_start_a) {
                    push_unique(v, b.lane);
                }
                if let Some(v) = lane_list(roads, b, !at_start_a) {
                    push_unique(v, a.lane);
                }
            }
            _ => {
                let id = net.lanelets.get(pair.from).map_or(0, |l| l.id.get());
                let to = net.lanelets.get(pair.to).map_or(0, |l| l.id.get());
                warnings.push(Warning::new(Subject::Lanelet(id), format!("its link to lanelet {to} joins the middle of a road; not written")));
            }
        }
    }
    // clusters of road ends
    let mut clusters: BTreeMap<usize, Vec<(LinkPair, End, End)>> = BTreeMap::new();
    for l in &across {
        let root = find(&mut parent, node(l.1));
        clusters.entry(root).or_default().push(*l);
    }
    let mut junctions: Vec<Junction> = Vec::new();
    let mut junction_of_inter: BTreeMap<u64, usize> = BTreeMap::new();
    for links in clusters.values() {
        let ends: BTreeSet<End> = links.iter().flat_map(|l| [l.1, l.2]).collect();
        let self_link = links.iter().any(|l| l.1 == l.2);
        let inters: BTreeSet<u64> = ends.iter().filter_map(|e| road_inter.get(&e.0).copied()).collect();
        let connecting = |e: &End, j: Option<u64>| j.is_some() && road_inter.get(&e.0).copied() == j;
        let set_link = |roads: &mut [Road], e: End, t: LinkTarget| {
            if let Some(r) = roads.get_mut(e.0) {
                if e.1 {
                    r.predecessor = Some(t);
                } else {
                    r.successor = Some(t);
                }
            }
        };
        let road_id = |roads: &[Road], e: End| roads.get(e.0).map_or(0, |r| r.id);
        let ends_v: Vec<End> = ends.iter().copied().collect();
        let inter_here = inters.iter().next().copied();
        if let ([a, b], false) = (ends_v.as_slice(), self_link) {
            let (ca, cb) = (connecting(a, inter_here), connecting(b, inter_here));
            if ca == cb {
                // road to road (both outside intersections, or both inside one)
                set_link(roads, *a, LinkTarget::Road { id: road_id(roads, *b), at_start: b.1 });
                set_link(roads, *b, LinkTarget::Road { id: road_id(roads, *a), at_start: a.1 });
                for (pair, ea, eb) in links {
                    let (Some(pa), Some(pb)) = (placed[pair.from], placed[pair.to]) else { continue };
                    if let Some(v) = lane_list(roads, pa, ea.1) {
                        push_unique(v, pb.lane);
                    }
                    if let Some(v) = lane_list(roads, pb, eb.1) {
                        push_unique(v, pa.lane);
                    }
                }
                continue;
            }
        }
        // a junction: the intersection's, else a direct one of its own
        let jidx = match inter_here {
            Some(x) => *junction_of_inter.entry(x).or_insert_with(|| {
                junctions.push(Junction { id: 0, name: format!("intersection {x}"), direct: false, connections: Vec::new() });
                junctions.len() - 1
            }),
            None => {
                junctions.push(Junction { id: 0, name: String::new(), direct: true, connections: Vec::new() });
                junctions.len() - 1
            }
        };
        if inters.len() > 1 {
            if let Some(x) = inters.iter().nth(1) {
                warnings.push(Warning::new(
                    Subject::Intersection(*x),
                    "its lanelets link directly to another intersection's; the link is written in that intersection's junction",
                ));
            }
        }
        let jid = first_junction_id + jidx as u64;
        let direct = junctions.get(jidx).is_some_and(|j| j.direct);
        for e in &ends_v {
            let is_conn = connecting(e, inter_here);
            if is_conn && ends_v.len() == 2 {
                // a connecting road meeting one road: the standard road link
                if let Some(other) = ends_v.iter().find(|x| *x != e) {
                    set_link(roads, *e, LinkTarget::Road { id: road_id(roads, *other), at_start: other.1 });
                }
            } else {
                set_link(roads, *e, LinkTarget::Junction { id: jid });
            }
            if is_conn {
                if let Some(r) = roads.get_mut(e.0) {
                    r.junction = Some(jid);
                }
            }
        }
        // connections: incoming = the road outside (or the link's source), target = the other
        let mut conns: BTreeMap<(u64, u64, bool), Vec<(i32, i32)>> = BTreeMap::new();
        for (pair, ea, eb) in links {
            let (Some(pa), Some(pb)) = (placed[pair.from], placed[pair.to]) else { continue };
            let swap = !direct && connecting(ea, inter_here) && !connecting(eb, inter_here);
            let ((inc_e, inc_lane), (tgt_e, tgt_lane)) = if swap { ((*eb, pb.lane), (*ea, pa.lane)) } else { ((*ea, pa.lane), (*eb, pb.lane)) };
            // a connecting road meeting a single road is linked by its road link already
            if !direct && ends_v.len() == 2 && connecting(&tgt_e, inter_here) {
                if let Some(v) = lane_list(roads, if swap { pa } else { pb }, tgt_e.1) {
                    push_unique(v, inc_lane);
                }
            }
            let v = conns.entry((road_id(roads, inc_e), road_id(roads, tgt_e), tgt_e.1)).or_default();
            if !v.contains(&(inc_lane, tgt_lane)) {
                v.push((inc_lane, tgt_lane));
            }
        }
        if let Some(j) = junctions.get_mut(jidx) {
            for ((incoming, target, at_start), lane_links) in conns {
                j.connections.push(Connection { incoming, target, target_at_start: at_start, lane_links });
            }
        }
    }
    for (k, j) in junctions.iter_mut().enumerate() {
        j.id = first_junction_id + k as u64;
        if j.name.is_empty() {
            j.name = format!("fork or merge {}", j.id);
        }
    }
    junctions
}

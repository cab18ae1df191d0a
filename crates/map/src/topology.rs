//! Predecessors and successors across lane sections, roads and junctions (default and
//! direct), in driving direction. Both views are used — "what follows my end" and "what
//! precedes my start" — so a link written on one side only still counts, and the result is
//! symmetric by construction (successor lists are made first, predecessor lists are their
//! mirror).

use crate::build::Built;
use crate::warn::WarningSink;
use commonroad::Lanelet;
use opendrive::{section_at_end, ContactPoint, LaneRef, RoadNetwork};

/// A link whose ends are further apart than this (m) is geometric nonsense for CommonRoad
/// (typically a lane closing to zero width whose OpenDRIVE successor is the lane it merges
/// into): it is dropped with a warning.
pub(crate) const MAX_LINK_GAP: f64 = 1.0;

/// Distance between the end of `a` and the start of `b` (the larger of left and right).
pub(crate) fn link_gap(a: &Lanelet, b: &Lanelet) -> f64 {
    let d = |p: Option<&commonroad::Point>, q: Option<&commonroad::Point>| match (p, q) {
        (Some(p), Some(q)) => (p.x - q.x).hypot(p.y - q.y),
        _ => f64::INFINITY,
    };
    d(a.bounds.left().last(), b.bounds.left().first()).max(d(a.bounds.right().last(), b.bounds.right().first()))
}

/// How many zero-length lane sections a link may pass through.
const MAX_PASS_THROUGH: u32 = 4;

/// Contact (in s terms of the lane's own section) where a lanelet begins / ends.
fn start_contact(along_s: bool) -> ContactPoint {
    if along_s {
        ContactPoint::Start
    } else {
        ContactPoint::End
    }
}

/// The end of `target`'s section reached when leaving `lane` through `end`.
fn arrival_contact(net: &RoadNetwork, lane: LaneRef, end: ContactPoint, target: LaneRef) -> ContactPoint {
    let Some(road) = net.roads.get(lane.road) else { return ContactPoint::Start };
    let last = road.lane_sections.len().saturating_sub(1);
    let inner = match end {
        ContactPoint::Start => lane.section > 0,
        ContactPoint::End => lane.section < last,
    };
    if inner {
        return end.opposite();
    }
    let Some(troad) = net.roads.get(target.road) else { return ContactPoint::Start };
    let mut ends: Vec<ContactPoint> = net
        .roads_at(lane.road, end)
        .into_iter()
        .filter(|e| e.road == target.road && section_at_end(troad, e.contact) == target.section)
        .map(|e| e.contact)
        .collect();
    ends.dedup();
    if let [only] = ends[..] {
        return only;
    }
    // ambiguous or unknown (e.g. a road joining both ends of one road): the nearer end
    let s_here = if end == ContactPoint::Start { 0.0 } else { road.length };
    let here = road.reference_pose(s_here);
    let d = |s: f64| {
        let p = troad.reference_pose(s);
        (p.x - here.x).hypot(p.y - here.y)
    };
    if d(0.0) <= d(troad.length) {
        ContactPoint::Start
    } else {
        ContactPoint::End
    }
}

/// Lanes (with the end of their section that is reached) continuing `lane` through `end`,
/// passing through zero-length sections.
fn reach(net: &RoadNetwork, built: &Built, lane: LaneRef, end: ContactPoint, depth: u32, out: &mut Vec<(LaneRef, ContactPoint)>) {
    for t in net.lanes_across(lane, end) {
        let c = arrival_contact(net, lane, end, t);
        if built.degenerate_sections.contains(&(t.road, t.section)) && depth < MAX_PASS_THROUGH {
            reach(net, built, t, c.opposite(), depth + 1, out);
        } else {
            out.push((t, c));
        }
    }
}

/// Fills predecessors and successors of every lanelet.
pub(crate) fn link(net: &RoadNetwork, built: &mut Built, warn: &mut WarningSink) {
    let n = built.lanelets.len();
    let mut succ: Vec<Vec<usize>> = vec![Vec::new(); n];
    for i in 0..n {
        let Some(o) = built.origins.get(i).copied() else { continue };
        let my_start = start_contact(o.along_s);
        let my_end = my_start.opposite();
        // what follows my end: lanelets that start where I arrive
        let mut found = Vec::new();
        reach(net, built, o.lane, my_end, 0, &mut found);
        for (t, c) in found {
            if let Some(&j) = built.index_of.get(&t) {
                if built.origins.get(j).is_some_and(|to| start_contact(to.along_s) == c) && j != i {
                    succ[i].push(j);
                }
            }
        }
        // what precedes my start: lanelets that end where I arrive
        let mut found = Vec::new();
        reach(net, built, o.lane, my_start, 0, &mut found);
        for (t, c) in found {
            if let Some(&j) = built.index_of.get(&t) {
                if built.origins.get(j).is_some_and(|to| start_contact(to.along_s).opposite() == c) && j != i {
                    if let Some(v) = succ.get_mut(j) {
                        v.push(i);
                    }
                }
            }
        }
    }
    let mut pred: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (i, list) in succ.iter_mut().enumerate() {
        list.sort_unstable();
        list.dedup();
        list.retain(|&j| {
            let (Some(a), Some(b)) = (built.lanelets.get(i), built.lanelets.get(j)) else { return false };
            let keep = link_gap(a, b) <= MAX_LINK_GAP;
            if !keep {
                let pos = built.origins.get(i).and_then(|o| net.roads.get(o.lane.road)).map(|r| r.pos).unwrap_or_default();
                warn.count(
                    &format!("lane links dropped: the lanes' ends are more than {MAX_LINK_GAP} m apart (e.g. a lane closing to zero width)"),
                    &net.file,
                    pos,
                );
            }
            keep
        });
        for &j in list.iter() {
            if let Some(p) = pred.get_mut(j) {
                p.push(i);
            }
        }
    }
    let ids: Vec<_> = built.lanelets.iter().map(|l| l.id).collect();
    for (i, l) in built.lanelets.iter_mut().enumerate() {
        let to_ids = |v: &Vec<usize>| v.iter().filter_map(|&k| ids.get(k).copied()).collect::<Vec<_>>();
        if let Some(v) = succ.get(i) {
            l.successors = to_ids(v);
        }
        if let Some(v) = pred.get_mut(i) {
            v.sort_unstable();
            v.dedup();
            l.predecessors = to_ids(v);
        }
    }
}

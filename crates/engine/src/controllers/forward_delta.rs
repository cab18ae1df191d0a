//! esmini's `Position::Delta` as its lead-finding controllers call it (`bothDirections` false):
//! the road path from one position forward (the way it faces) to another, searched by
//! `RoadPath::Calculate`'s Dijkstra over road links, and the lane difference and lateral offset
//! of the second position as seen from the first's lane carried along that path. Unlike the
//! engine's general road distance it follows esmini's own rules: intermediate roads only where
//! the lane goes on (`RoadPath::CheckRoad`), but the target's road found through *any*
//! connection of a junction leading to it (a lead turning off on another branch still counts),
//! at most 100 expansions, stopping once the distance reached passes the look-ahead.

use super::lane_router::connected_lane_at_s;
use super::lane_router::connecting_lane_id;
use super::natural_driver::view::LARGE_NUMBER;
use crate::roads::lane_geometry::lane_center_t;
use crate::roads::lane_side::{lane_delta, side};
use crate::roads::LanePos;
use opendrive::{ContactPoint, ElementType, JunctionType, RoadNetwork};

/// RoadPath::Calculate's cap on expansions.
const MAX_EXPANSIONS: usize = 100;

/// What `Position::Delta` reports: `ds` along the path (negative behind), `d_lane` the lane
/// difference (by one less across the centre lane) and `dt` the lateral difference.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Delta {
    pub ds: f64,
    pub d_lane: i32,
    pub dt: f64,
}

/// A RoadPath::PathNode: the link at `end` of `road`, the distance to it and the lane
/// (`from_lane`) the path holds on `road` at that end.
#[derive(Debug, Clone, Copy)]
struct Node {
    dist: f64,
    road: usize,
    end: ContactPoint,
    from_lane: i32,
}

/// esmini's `Position::Delta(pos_b, diff, false, max)` from `a` (world heading `a_h`) to `b`;
/// `None` where it returns false (no path forward, or not within `max`).
pub(crate) fn forward_delta(net: &RoadNetwork, a: &LanePos, a_h: f64, b: &LanePos, max: f64) -> Option<Delta> {
    let ra = net.roads.get(a.road)?;
    let rb = net.roads.get(b.road)?;
    let t = |p: &LanePos, r: &opendrive::Road| lane_center_t(r, p.lane_id, p.s).map(|c| c + p.offset);
    let (ta, tb) = (t(a, ra)?, t(b, rb)?);
    let forward = a.dir > 0.0;
    let (ds, last) = if a.road == b.road {
        // RoadPath::Calculate's special case: the s difference, seen the way `a` faces.
        ((b.s - a.s) * if forward { 1.0 } else { -1.0 }, None)
    } else {
        let (d, last) = search(net, a, forward, b, max)?;
        // Calculate turns the sign for a start position facing against its lane's driving
        // direction (GetHRelativeDrivingDirection in (pi/2, 3pi/2): an angle difference in
        // [-pi, pi], so only one turned to the left of it).
        let road_h = a.pose(net)?.road_heading;
        // GetDrivingDirection's wrapped arithmetic against the entity's heading as the
        // controller holds it: composing it with the road's (EvaluateHPR, as for
        // SynchronizeAction) turned a car facing along s on a road ending at heading 2π by π
        // (s59059_00475, where esmini keeps its lead), so the heading is taken as it is
        let against = crate::roads::driving_direction::faces_against(ra.rule, a.lane_id, road_h, a_h);
        (if against { -d } else { d }, Some(last))
    };
    if ds.abs() >= max {
        return None;
    }
    // Position::Delta: a's lane carried along the path's last road onto b's road and to b's s.
    let mut adj = a.lane_id;
    if let Some(n) = last {
        let len = net.roads.get(n.road).map_or(0.0, |r| r.length);
        let (from_s, to_s, b_from) = match n.end {
            ContactPoint::Start => (len, 0.0, 0.0),
            ContactPoint::End => (0.0, len, rb.length),
        };
        adj = connected_lane_at_s(net, n.road, n.from_lane, from_s, to_s);
        adj = connecting_lane_id(net, (n.road, n.end), adj, b.road);
        adj = connected_lane_at_s(net, b.road, adj, b_from, b.s);
    }
    let d_lane = lane_delta(adj, b.lane_id);
    let dt = if side(adj) == side(a.lane_id) { tb - ta } else { tb + ta };
    Some(Delta { ds, d_lane, dt })
}

/// RoadPath::Calculate forward from `a` to `b`'s road (≠ `a`'s): the distance and the node
/// whose link reached it. It stops expanding once the nearest queued link is `max` away.
fn search(net: &RoadNetwork, a: &LanePos, forward: bool, b: &LanePos, max: f64) -> Option<(f64, Node)> {
    let ra = net.roads.get(a.road)?;
    let rb = net.roads.get(b.road)?;
    let end = if forward { ContactPoint::End } else { ContactPoint::Start };
    ra.link_at(end)?;
    let (lane, dist) = match end {
        ContactPoint::End => (connected_lane_at_s(net, a.road, a.lane_id, a.s, ra.length), ra.length - a.s),
        ContactPoint::Start => (connected_lane_at_s(net, a.road, a.lane_id, a.s, 0.0), a.s),
    };
    let mut unvisited = vec![Node { dist, road: a.road, end, from_lane: lane }];
    let mut visited: Vec<Node> = Vec::new();
    let along_b = |contact: Option<ContactPoint>| if contact == Some(ContactPoint::Start) { b.s } else { rb.length - b.s };
    let mut tmp = 0.0;
    let mut found = false;
    let mut i = 0;
    while i < MAX_EXPANSIONS && !found && !unvisited.is_empty() && tmp < max {
        i += 1;
        // The first node of strictly smallest distance (index 0 if none is below LARGE_NUMBER).
        let mut k = 0;
        let mut min = LARGE_NUMBER;
        for (j, n) in unvisited.iter().enumerate() {
            if n.dist < min {
                k = j;
                min = n.dist;
            }
        }
        let node = unvisited[k];
        tmp = node.dist;
        let link = net.roads.get(node.road).and_then(|r| r.link_at(node.end));
        match link {
            Some(l) if l.element_type == ElementType::Road => {
                if let Some(next) = net.road_index(&l.element_id) {
                    if next == b.road {
                        tmp += along_b(l.contact_point);
                        found = true;
                    } else {
                        check_road(net, next, &node, &visited, &mut unvisited);
                    }
                }
            }
            Some(_) => {
                // Every connection whose incoming road is this one, in esmini's order (its
                // counter connections too: `road_path::next_roads`); reaching the target's road
                // by several adds its part once for each (as esmini does).
                for e in crate::roads::road_path::next_roads(net, node.road, node.end) {
                    let (next, contact) = (e.road, e.contact);
                    if next == b.road {
                        tmp += along_b(Some(contact));
                        found = true;
                    } else {
                        check_road(net, next, &node, &visited, &mut unvisited);
                    }
                }
            }
            None => {}
        }
        visited.push(unvisited.remove(k));
    }
    if !found {
        return None;
    }
    Some((tmp, *visited.last()?))
}

/// RoadPath::CheckRoad: step from `src`'s link onto `check` when `src`'s lane continues there,
/// queueing the link at `check`'s far end (always as a new node, as esmini's list scan leaves
/// its index at the end; an equal link already queued only gets the shorter distance).
fn check_road(net: &RoadNetwork, check: usize, src: &Node, visited: &[Node], unvisited: &mut Vec<Node>) {
    let lane = connecting_lane_id(net, (src.road, src.end), src.from_lane, check);
    if lane == 0 {
        return;
    }
    let (Some(from), Some(road)) = (net.roads.get(src.road), net.roads.get(check)) else { return };
    let Some(src_link) = from.link_at(src.end) else { return };
    let links_to = |end: ContactPoint, id: &str| road.link_at(end).is_some_and(|l| l.element_id == id);
    let next_end = match src_link.element_type {
        ElementType::Road => {
            if src_link.contact_point == Some(ContactPoint::End) {
                ContactPoint::Start
            } else {
                ContactPoint::End
            }
        }
        ElementType::Junction => {
            let direct = net.junction(&src_link.element_id).is_some_and(|j| j.kind == JunctionType::Direct);
            let id = if direct { src_link.element_id.as_str() } else { from.id.as_str() };
            if links_to(ContactPoint::End, id) {
                ContactPoint::Start
            } else if links_to(ContactPoint::Start, id) {
                ContactPoint::End
            } else {
                return;
            }
        }
    };
    if road.link_at(next_end).is_none() {
        return;
    }
    let lane = match next_end {
        ContactPoint::Start => connected_lane_at_s(net, check, lane, road.length, 0.0),
        ContactPoint::End => connected_lane_at_s(net, check, lane, 0.0, road.length),
    };
    if visited.iter().any(|n| n.road == check && n.end == next_end) {
        return;
    }
    let dist = src.dist + road.length;
    for u in unvisited.iter_mut().filter(|u| u.road == check && u.end == next_end) {
        if dist < u.dist {
            u.dist = dist;
        }
    }
    unvisited.push(Node { dist, road: check, end: next_end, from_lane: lane });
}

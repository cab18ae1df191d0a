//! The lane-independent path search of esmini's FollowRoute controller (esmini's
//! `LaneIndependentRouter`): a Dijkstra over (road, lane) nodes in which every same-side
//! driving lane at a road's end may lead on, so the path says on which lane to leave each
//! road; and the waypoints the controller steers by (one per road on the path, then the
//! target). The open set is a binary heap kept exactly as libstdc++'s `std::priority_queue`
//! keeps it, because esmini breaks equal weights by that heap's order.

use crate::roads::junction_connections;
use opendrive::{ContactPoint, ElementType, JunctionType, Road, RoadKind, RoadLink, RoadNetwork};
use routing::Strategy;

/// esmini's LARGE_NUMBER: the weight of a road nobody can drive on.
const LARGE_NUMBER: f64 = 1e10;
/// esmini's default speed for a road without types or of an unlisted type, m/s.
const DEFAULT_SPEED: f64 = 19.444;

/// A place on a lane: road index, lane id, s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct LaneSpot {
    pub road: usize,
    pub lane: i32,
    pub s: f64,
}

/// A road's link at one end: the road's index and the end (End = successor link).
type Link = (usize, ContactPoint);

#[derive(Debug, Clone, Copy)]
pub(crate) struct Node {
    pub road: usize,
    pub current_lane: i32,
    pub from_lane: i32,
    weight: f64,
    link: Option<Link>,
    previous: Option<usize>,
}

fn link_of(net: &RoadNetwork, l: Link) -> Option<&RoadLink> {
    net.roads.get(l.0)?.link_at(l.1)
}

/// The lane section a link leaves from: the last for a successor link, else the first.
fn end_section(road: &Road, end: ContactPoint) -> usize {
    match end {
        ContactPoint::End => road.lane_sections.len().saturating_sub(1),
        ContactPoint::Start => 0,
    }
}

/// esmini's `RoadCalculations::CalcAverageSpeed`: the mean over the road's type records of
/// each record's speed, or its type's default speed.
pub(crate) fn average_speed(road: &Road) -> f64 {
    if road.types.is_empty() {
        return DEFAULT_SPEED;
    }
    let mut total = 0.0;
    for t in &road.types {
        let given = t.speed.as_ref().and_then(|s| s.max_mps).filter(|v| *v > 1e-10);
        let default = match t.kind {
            RoadKind::Pedestrian | RoadKind::Bicycle => 1.389,
            RoadKind::LowSpeed | RoadKind::TownPlayStreet | RoadKind::TownPrivate => 8.333,
            RoadKind::Town | RoadKind::TownLocal => 13.888,
            RoadKind::Rural | RoadKind::Unknown => 19.444,
            RoadKind::Motorway => 25.0,
            _ => DEFAULT_SPEED,
        };
        total += given.unwrap_or(default);
    }
    total / road.types.len() as f64
}

/// esmini's `Road::GetConnectingLaneId`: the lane `from_lane` of `road` leads to on
/// `next_road` across link `link`; 0 for none. Through a default junction by esmini's
/// connections (its counter connections too: `junction_connections::entering`), through a
/// direct one by the connection to the linked road, else by the counter connection esmini adds
/// for it (OpenDrive::CheckJunctionConnection: incoming and linked road swapped, lane links
/// turned round); across a road link by the lane's own link.
pub(crate) fn connecting_lane_id(net: &RoadNetwork, link: Link, from_lane: i32, next_road: usize) -> i32 {
    let Some(road) = net.roads.get(link.0) else { return 0 };
    let Some(rl) = road.link_at(link.1) else { return 0 };
    let Some(lane) = road.lane_sections.get(end_section(road, link.1)).and_then(|s| s.lane(from_lane)) else { return 0 };
    let Some(next) = net.roads.get(next_road) else { return 0 };
    match rl.element_type {
        ElementType::Road => {
            if rl.element_id != next.id {
                return 0;
            }
            let ids = if link.1 == ContactPoint::End { &lane.successors } else { &lane.predecessors };
            ids.first().copied().unwrap_or(0)
        }
        ElementType::Junction => {
            let Some(ji) = net.junction_index(&rl.element_id) else { return 0 };
            let Some(j) = net.junctions.get(ji) else { return 0 };
            if j.kind != JunctionType::Direct {
                return junction_connections::entering(net, ji, link.0)
                    .iter()
                    .filter(|c| c.connecting == next_road)
                    .find_map(|c| c.lane_links.iter().find(|l| l.0 == from_lane).map(|l| l.1))
                    .unwrap_or(0);
            }
            let (id, next_id) = (Some(road.id.as_str()), Some(next.id.as_str()));
            let forward = j
                .connections
                .iter()
                .filter(|c| c.incoming_road.as_deref() == id && c.target_road() == next_id)
                .find_map(|c| c.lane_links.iter().find(|l| l.from == from_lane).map(|l| l.to));
            let counter = || {
                j.connections
                    .iter()
                    .filter(|c| c.target_road() == id && c.incoming_road.as_deref() == next_id)
                    .find_map(|c| c.lane_links.iter().find(|l| l.to == from_lane).map(|l| l.from))
            };
            forward.or_else(counter).unwrap_or(0)
        }
    }
}

/// esmini's `Road::GetConnectedLaneIdAtS`: the lane `lane` at `s_start` runs into through
/// the road's lane sections towards `s_target`. esmini steps while the start of the section
/// it just crossed is short of the target, so it follows the lane one section past the one
/// holding the target.
pub(crate) fn connected_lane_at_s(net: &RoadNetwork, road: usize, lane: i32, s_start: f64, s_target: f64) -> i32 {
    let Some(r) = net.roads.get(road) else { return 0 };
    let n = r.lane_sections.len();
    if n == 0 {
        return 0;
    }
    let link = |j: usize, id: i32, succ: bool| -> i32 {
        match r.lane_sections.get(j).and_then(|sec| sec.lane(id)) {
            None => 0,
            Some(l) => {
                let ids = if succ { &l.successors } else { &l.predecessors };
                ids.first().copied().unwrap_or(id)
            }
        }
    };
    let mut id = lane;
    let mut j = r.section_index_at(s_start);
    let mut s = s_start;
    if s_target > s_start - crate::dynamics::ESMINI_SMALL_NUMBER {
        while id != 0 && j < n - 1 && s < s_target {
            id = link(j, id, true);
            s = r.lane_sections[j].s;
            j += 1;
        }
    } else {
        while id != 0 && j > 0 && s > s_target {
            id = link(j, id, false);
            s = r.lane_sections[j].s;
            j -= 1;
        }
    }
    id
}

/// Roads a link leads to (esmini's `GetNextRoads`): the linked road, or the road of every
/// connection of the junction whose incoming road is `road`, in esmini's order, its counter
/// connections too — a direct junction's lead to its linked roads (`road_path::next_roads`).
pub(crate) fn next_roads(net: &RoadNetwork, link: Link) -> Vec<usize> {
    let Some(road) = net.roads.get(link.0) else { return Vec::new() };
    let Some(rl) = road.link_at(link.1) else { return Vec::new() };
    match rl.element_type {
        ElementType::Road => net.road_index(&rl.element_id).into_iter().collect(),
        ElementType::Junction => crate::roads::road_path::next_roads(net, link.0, link.1).into_iter().map(|e| e.road).collect(),
    }
}

/// The weight of driving `length` metres of `road` after `previous` (esmini's `CalcWeight`).
fn weight(net: &RoadNetwork, previous: &Node, strategy: Strategy, length: f64, road: &Road) -> f64 {
    // ScenarioReader reads a waypoint's routeStrategy as SHORTEST unless it says fastest or
    // leastIntersections: `random` is planned as the shortest way (CalcWeight's RANDOM branch,
    // weight 0, is never reached).
    match strategy {
        Strategy::Shortest | Strategy::Random => length,
        Strategy::Fastest => {
            let v = average_speed(road);
            if v == 0.0 {
                LARGE_NUMBER
            } else {
                length / v
            }
        }
        Strategy::LeastIntersections => {
            let through_junction = previous.link.and_then(|l| link_of(net, l)).is_some_and(|rl| rl.element_type == ElementType::Junction);
            if through_junction {
                1.0
            } else {
                0.0
            }
        }
    }
}

/// The link at the far end of `next_road` when entered from `node` (esmini's `GetNextLink`).
fn next_link(net: &RoadNetwork, node: &Node, next_road: usize) -> Option<Link> {
    let rl = link_of(net, node.link?)?;
    let nr = net.roads.get(next_road)?;
    let exists = |end: ContactPoint| nr.link_at(end).map(|_| (next_road, end));
    match rl.element_type {
        ElementType::Road => {
            if rl.contact_point == Some(ContactPoint::End) {
                exists(ContactPoint::Start)
            } else {
                exists(ContactPoint::End)
            }
        }
        ElementType::Junction => {
            let direct = net.junction(&rl.element_id).is_some_and(|j| j.kind == JunctionType::Direct);
            let element = if direct { rl.element_id.as_str() } else { net.roads.get(node.road)?.id.as_str() };
            if nr.successor.as_ref().is_some_and(|l| l.element_id == element) {
                exists(ContactPoint::Start)
            } else if nr.predecessor.as_ref().is_some_and(|l| l.element_id == element) {
                exists(ContactPoint::End)
            } else {
                None
            }
        }
    }
}

/// libstdc++'s `std::priority_queue` over node indices with esmini's `WeightCompare`.
struct Heap {
    items: Vec<usize>,
}

impl Heap {
    /// esmini's `WeightCompare(a, b)`: true when `a` is popped after `b` (heavier; at equal
    /// weight, the one changing lanes more).
    fn less(nodes: &[Node], a: usize, b: usize) -> bool {
        let (na, nb) = (&nodes[a], &nodes[b]);
        if na.weight == nb.weight {
            let jump = |n: &Node| n.previous.map_or(0, |p| (n.current_lane - nodes[p].current_lane).abs());
            jump(na) > jump(nb)
        } else {
            na.weight > nb.weight
        }
    }

    fn push_hole(&mut self, nodes: &[Node], mut hole: usize, top: usize, value: usize) {
        while hole > top {
            let parent = (hole - 1) / 2;
            if !Self::less(nodes, self.items[parent], value) {
                break;
            }
            self.items[hole] = self.items[parent];
            hole = parent;
        }
        self.items[hole] = value;
    }

    fn push(&mut self, nodes: &[Node], v: usize) {
        self.items.push(v);
        let last = self.items.len() - 1;
        self.push_hole(nodes, last, 0, v);
    }

    fn pop(&mut self, nodes: &[Node]) -> Option<usize> {
        let len = self.items.len();
        if len == 0 {
            return None;
        }
        let top = self.items[0];
        if len > 1 {
            // pop_heap: the last element goes into the hole left at the top (__adjust_heap).
            let value = self.items[len - 1];
            self.items[len - 1] = top;
            let n = len - 1;
            let mut hole = 0;
            let mut child = 0;
            while child < (n.saturating_sub(1)) / 2 {
                child = 2 * (child + 1);
                if Self::less(nodes, self.items[child], self.items[child - 1]) {
                    child -= 1;
                }
                self.items[hole] = self.items[child];
                hole = child;
            }
            if n % 2 == 0 && n >= 2 && child == (n - 2) / 2 {
                child = 2 * (child + 1);
                self.items[hole] = self.items[child - 1];
                hole = child - 1;
            }
            self.push_hole(nodes, hole, 0, value);
        }
        self.items.pop();
        Some(top)
    }
}

fn same_node(a: &Node, b: &Node) -> bool {
    a.road == b.road && a.current_lane == b.current_lane && a.from_lane == b.from_lane && a.link == b.link
}

/// Whether a place is on an existing driving lane of its road (esmini's `IsPositionValid`).
fn valid(net: &RoadNetwork, p: &LaneSpot) -> bool {
    let Some(r) = net.roads.get(p.road) else { return false };
    if p.s > r.length || p.s < 0.0 {
        return false;
    }
    r.lane_sections.get(r.section_index_at(p.s)).and_then(|s| s.lane(p.lane)).is_some_and(|l| l.kind.is_any_driving())
}

/// esmini's `LaneIndependentRouter::CalculatePath`: the nodes from `start` (driving along s
/// when `forward`) to `target`; empty when there is none, including when both are on the
/// same lane of the same road.
pub(crate) fn calculate_path(net: &RoadNetwork, start: LaneSpot, forward: bool, target: LaneSpot, strategy: Strategy) -> Vec<Node> {
    if !valid(net, &start) || !valid(net, &target) {
        return Vec::new();
    }
    let Some(start_road) = net.roads.get(start.road) else { return Vec::new() };
    let end = if forward { ContactPoint::End } else { ContactPoint::Start };
    if start.road == target.road && start.lane == target.lane {
        return Vec::new();
    }
    if start_road.link_at(end).is_none() {
        return Vec::new();
    }
    let first_length = if forward { start_road.length - start.s } else { start.s };
    let first_weight = match strategy {
        Strategy::Shortest | Strategy::Random => first_length,
        Strategy::Fastest => first_length / average_speed(start_road),
        Strategy::LeastIntersections => 0.0,
    };
    let mut nodes =
        vec![Node { road: start.road, current_lane: start.lane, from_lane: 0, weight: first_weight, link: Some((start.road, end)), previous: None }];
    let mut heap = Heap { items: Vec::new() };
    heap.push(&nodes, 0);
    let mut visited: Vec<usize> = Vec::new();
    let mut found = false;
    while let Some(cur) = heap.pop(&nodes) {
        if visited.iter().any(|&v| same_node(&nodes[v], &nodes[cur])) {
            continue;
        }
        visited.push(cur);
        let node = nodes[cur];
        if node.road == target.road && node.current_lane == target.lane {
            found = true;
            break;
        }
        let Some(link) = node.link else { continue };
        let Some(road) = net.roads.get(node.road) else { continue };
        let Some(section) = road.lane_sections.get(end_section(road, link.1)) else { continue };
        for next_road in next_roads(net, link) {
            let Some(nr) = net.roads.get(next_road) else { continue };
            // esmini's GetConnectingLanes: every driving lane on the node's side of the road.
            for lane in section.lanes_left_to_right() {
                if lane.id == 0 || !lane.kind.is_any_driving() || lane.id.signum() != node.current_lane.signum() {
                    continue;
                }
                let to = connecting_lane_id(net, link, lane.id, next_road);
                if to == 0 {
                    continue;
                }
                let n = if next_road == target.road && to == target.lane {
                    let contact = link_of(net, link).and_then(|rl| rl.contact_point);
                    let length = match contact {
                        Some(ContactPoint::Start) => target.s,
                        Some(ContactPoint::End) => nr.length - target.s,
                        None => 0.0,
                    };
                    Node {
                        road: next_road,
                        current_lane: to,
                        from_lane: lane.id,
                        weight: node.weight + weight(net, &node, strategy, length, nr),
                        link: None,
                        previous: Some(cur),
                    }
                } else {
                    let Some(nl) = next_link(net, &node, next_road) else { continue };
                    Node {
                        road: next_road,
                        current_lane: to,
                        from_lane: lane.id,
                        weight: node.weight + weight(net, &node, strategy, nr.length, nr),
                        link: Some(nl),
                        previous: Some(cur),
                    }
                };
                nodes.push(n);
                heap.push(&nodes, nodes.len() - 1);
            }
        }
    }
    if !found {
        return Vec::new();
    }
    let mut path = Vec::new();
    let mut it = visited.last().copied();
    while let Some(i) = it {
        path.push(nodes[i]);
        it = nodes[i].previous;
    }
    path.reverse();
    path
}

/// esmini's `LaneIndependentRouter::GetWaypoints`: for each road on the path but the last, a
/// waypoint on the lane that leads on, in the middle of the stretch where that lane is a
/// driving lane up to the road's end (or at the start when that is further along); then the
/// target.
pub(crate) fn path_waypoints(net: &RoadNetwork, path: &[Node], start: LaneSpot, target: LaneSpot) -> Vec<LaneSpot> {
    let mut out = Vec::with_capacity(path.len());
    for (idx, pair) in path.windows(2).enumerate() {
        let (cur, next) = (&pair[0], &pair[1]);
        let Some(road) = net.roads.get(cur.road) else { continue };
        let secs = &road.lane_sections;
        let sec_len = |i: usize| secs.get(i + 1).map_or(road.length, |n| n.s) - secs[i].s;
        let drives = |i: usize| secs[i].lane(next.from_lane).is_some_and(|l| l.kind.is_any_driving());
        let mut lane_length = 0.0;
        let s = if cur.link.map(|l| l.1) == Some(ContactPoint::End) {
            for i in (0..secs.len()).rev() {
                if !drives(i) {
                    break;
                }
                lane_length += sec_len(i);
            }
            if idx == 0 && start.s > road.length - lane_length {
                start.s
            } else {
                road.length - lane_length / 2.0
            }
        } else {
            for i in 0..secs.len() {
                if !drives(i) {
                    break;
                }
                lane_length += sec_len(i);
            }
            if idx == 0 && start.s < lane_length {
                start.s
            } else {
                lane_length / 2.0
            }
        };
        out.push(LaneSpot { road: cur.road, lane: next.from_lane, s });
    }
    out.push(target);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(weight: f64) -> Node {
        Node { road: 0, current_lane: -1, from_lane: 0, weight, link: None, previous: None }
    }

    #[test]
    fn equal_weights_pop_in_libstdcpp_heap_order() {
        // std::priority_queue with all keys equal: push_heap never moves an element, so the
        // vector is [a, b, c, d]; pop_heap moves the hole down to the right child (c) and puts
        // d back at the end: [c, b, d]; then [b, d]. Pop order a, c, b, d (worked by hand from
        // libstdc++'s __adjust_heap / __push_heap).
        let nodes = vec![node(1.0); 4];
        let mut h = Heap { items: Vec::new() };
        for i in 0..4 {
            h.push(&nodes, i);
        }
        let order: Vec<usize> = std::iter::from_fn(|| h.pop(&nodes)).collect();
        assert_eq!(order, vec![0, 2, 1, 3]);
    }

    #[test]
    fn lighter_nodes_pop_first() {
        let nodes: Vec<Node> = [5.0, 1.0, 4.0, 2.0, 3.0].iter().map(|&w| node(w)).collect();
        let mut h = Heap { items: Vec::new() };
        for i in 0..nodes.len() {
            h.push(&nodes, i);
        }
        let order: Vec<f64> = std::iter::from_fn(|| h.pop(&nodes)).map(|i| nodes[i].weight).collect();
        assert_eq!(order, vec![1.0, 2.0, 3.0, 4.0, 5.0]);
    }

    #[test]
    fn the_path_to_a_junction_exit_runs_through_its_connecting_road() {
        // tests/fixtures/fork.xodr: road 1 (100 m) → junction: road 10 (straight, 20 m) to
        // road 2, road 11 (left arc, 10π m) to road 3.
        let net = opendrive::load(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/fork.xodr")).expect("fixture").network;
        let idx = |id: &str| net.road_index(id).expect("road");
        let start = LaneSpot { road: idx("1"), lane: -1, s: 10.0 };
        let target = LaneSpot { road: idx("3"), lane: -1, s: 50.0 };
        let path = calculate_path(&net, start, true, target, Strategy::Shortest);
        let roads: Vec<usize> = path.iter().map(|n| n.road).collect();
        assert_eq!(roads, vec![idx("1"), idx("11"), idx("3")]);
        // Weights: 90 m left on road 1, the whole arc, then 50 m into road 3 (its link to
        // road 3 has contact point start).
        assert!((path[2].weight - (90.0 + 10.0 * std::f64::consts::PI + 50.0)).abs() < 1e-9);
        // Waypoints: on road 1 where Ego is (lane −1 drives to the end of the road, and Ego is
        // past its start), mid-arc on road 11, then the target.
        let w = path_waypoints(&net, &path, start, target);
        assert_eq!(w.len(), 3);
        assert_eq!((w[0].road, w[0].lane, w[0].s), (idx("1"), -1, 10.0));
        assert!(w[1].road == idx("11") && w[1].lane == -1 && (w[1].s - 5.0 * std::f64::consts::PI).abs() < 1e-9);
        assert_eq!(w[2], target);
        // Same road and lane: no path (esmini logs an error and the controller gives up).
        assert!(calculate_path(&net, start, true, LaneSpot { s: 90.0, ..start }, Strategy::Shortest).is_empty());
    }
}

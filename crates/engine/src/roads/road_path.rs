//! The shape of the road path between two road positions as esmini's `Position::Delta` uses
//! it for a lateral distance (RoadPath::Calculate): a shortest chain of linked roads searched
//! from the first position in both directions, following its lane (RoadPath::CheckRoad drops
//! a road its lane does not continue into, Road::GetConnectingLaneId): which end of the first
//! road it leaves by, which end of the last road before the second position's road it leaves
//! by, whether a lane id keeps its sign along the chain, and its length (a SynchronizeAction's
//! distances).

use opendrive::{section_at_end, ContactPoint, ElementType, JunctionType, LaneRef, RoadEnd, RoadNetwork};

/// Most road ends the search settles (hostile input: bounded work per call).
const MAX_SETTLED: usize = 512;

/// The ends of the path from road `a` to another road (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PathEnds {
    /// The end of road `a` the path leaves by.
    pub first_exit: ContactPoint,
    /// The end of the last road before the target road that the path leaves by.
    pub last_exit: ContactPoint,
    /// Lane ids change sign along the path (an odd number of end-to-end or start-to-start
    /// links: the roads run against each other).
    pub lanes_flip: bool,
    /// The end of the target road the path enters by, and the distance to it from the first
    /// position (RoadPath::Calculate's distance less the part on the target road).
    pub entry: ContactPoint,
    pub to_entry: f64,
    /// The first position's lane carried along the path into the target road at its `entry`
    /// end (Road::GetConnectingLaneId across the last link); 0 where it does not continue.
    pub entry_lane: i32,
}

impl PathEnds {
    /// RoadPath::Calculate's (unsigned) length of the path to s `sb` on the target road of
    /// length `length_b`.
    pub(crate) fn length_to(&self, sb: f64, length_b: f64) -> f64 {
        self.to_entry
            + match self.entry {
                ContactPoint::Start => sb,
                ContactPoint::End => length_b - sb,
            }
    }
}

/// One reached road end: distance so far, road, the end it was entered by, the lane entered
/// by, and the path's first exit, last exit and lane flip up to it.
type Reached = (f64, usize, ContactPoint, i32, ContactPoint, ContactPoint, bool);

/// The path from (road `a`, s `sa`, lane `lane_a`) to road `b` ≠ `a`; `None` when no chain of
/// linked roads joins them. As esmini's Dijkstra the nearest road end is expanded first, the
/// start of road `a` before its end on a tie.
pub(crate) fn path_ends(net: &RoadNetwork, a: usize, sa: f64, lane_a: i32, b: usize) -> Option<PathEnds> {
    if a == b {
        return None;
    }
    let ra = net.roads.get(a)?;
    let mut frontier: Vec<Reached> = Vec::new();
    let mut settled: Vec<(usize, ContactPoint)> = Vec::new();
    let section_a = ra.section_index_at(sa);
    let push = |frontier: &mut Vec<Reached>, road: usize, section: usize, lane: i32, exit: ContactPoint, d: f64, first: Option<ContactPoint>, flip: bool| {
        // The lane at the end left by (Road::GetConnectedLaneIdAtS across the lane sections).
        // Where it stops, lane 0: no step but to the target road.
        let lane = lane_to_end(net, LaneRef { road, section, lane }, exit).unwrap_or(0);
        let beyond = net.lanes_across(LaneRef { road, section: net.roads.get(road).map_or(0, |r| section_at_end(r, exit)), lane }, exit);
        for e in next_roads(net, road, exit) {
            // RoadPath::CheckRoad: a road the lane does not continue into is no step, unless
            // it is the target (reached before its lane is looked at).
            let next_lane = beyond.iter().find(|l| l.road == e.road).map(|l| l.lane);
            let Some(next_lane) = next_lane.or((e.road == b).then_some(0)) else { continue };
            // Entering by the same kind of end as left by turns the lane numbering around.
            let f = flip ^ (e.contact == exit);
            frontier.push((d, e.road, e.contact, next_lane, first.unwrap_or(exit), exit, f));
        }
    };
    push(&mut frontier, a, section_a, lane_a, ContactPoint::Start, sa.clamp(0.0, ra.length), None, false);
    push(&mut frontier, a, section_a, lane_a, ContactPoint::End, (ra.length - sa).max(0.0), None, false);
    while settled.len() < MAX_SETTLED {
        // The first of the nearest, as esmini's strict minimum over its list in order.
        let mut k = None;
        for (i, r) in frontier.iter().enumerate() {
            if k.map_or(true, |j: usize| r.0 < frontier[j].0) {
                k = Some(i);
            }
        }
        let (d, road, entry, lane, first, last, flip) = frontier.remove(k?);
        if settled.contains(&(road, entry)) {
            continue;
        }
        settled.push((road, entry));
        if road == b {
            return Some(PathEnds { first_exit: first, last_exit: last, lanes_flip: flip, entry, to_entry: d, entry_lane: lane });
        }
        let Some(r) = net.roads.get(road) else { continue };
        push(&mut frontier, road, section_at_end(r, entry), lane, entry.opposite(), d + r.length, Some(first), flip);
    }
    None
}

/// Position::Delta's lane of (road `a`, s `sa`, lane `lane_a`) on road `b` at s `sb`: the same
/// lane on one road; else the lane the path to `b` enters it by, carried across `b`'s lane
/// sections to `sb` (Road::GetConnectedLaneIdAtS) from the end esmini takes
/// ([`PathEnds::carried_lane`]), 0 where the lane does not continue; `None`
/// where no path joins the roads.
pub(crate) fn lane_carried(net: &RoadNetwork, a: usize, sa: f64, lane_a: i32, b: usize, sb: f64) -> Option<i32> {
    if a == b {
        return Some(lane_a);
    }
    path_ends(net, a, sa, lane_a, b)?.carried_lane(net, b, sb)
}

impl PathEnds {
    /// `lane_carried`'s lane on the path's last road `b` at s `sb`.
    pub(crate) fn carried_lane(&self, net: &RoadNetwork, b: usize, sb: f64) -> Option<i32> {
        let rb = net.roads.get(b)?;
        let target = rb.section_index_at(sb);
        // Position::Delta carries the lane across `b` from the end last_node->contactPoint
        // names: the end by which the path leaves the road before `b`, not the end by which it
        // enters `b` (entered at its end from a road left by its start, the lane is carried
        // from `b`'s start).
        let from = self.last_exit;
        let mut lane = LaneRef { road: b, section: section_at_end(rb, from), lane: self.entry_lane };
        while lane.lane != 0 && lane.section != target {
            lane = net.lanes_across(lane, from.opposite()).first().copied().filter(|l| l.road == b).unwrap_or(LaneRef { lane: 0, ..lane });
        }
        Some(lane.lane)
    }

    /// Position::Delta's dt is tB + tA (not tB − tA) when SIGN(adjustedLaneIdA) differs from
    /// SIGN(laneIdA), SIGN(0) = +1: a lane that does not continue onto `b` (carried lane 0)
    /// turns the sum on for a start lane on the right (negative ids).
    pub(crate) fn dt_flips(&self, net: &RoadNetwork, b: usize, sb: f64, lane_a: i32) -> bool {
        match self.carried_lane(net, b, sb) {
            Some(c) => (c < 0) != (lane_a < 0),
            None => self.lanes_flip,
        }
    }
}

/// The lane `lane` continues into at the `end` of its road, section by section (the first
/// link of each, as esmini's Road::GetConnectedLaneIdAtS); `None` where it stops.
fn lane_to_end(net: &RoadNetwork, mut lane: LaneRef, end: ContactPoint) -> Option<i32> {
    let last = section_at_end(net.roads.get(lane.road)?, end);
    while lane.section != last {
        lane = *net.lanes_across(lane, end).first()?;
    }
    Some(lane.lane)
}

/// The roads the search steps to from `road`'s end `exit`. Into a junction esmini's
/// RoadPath::Calculate takes only the connections whose incoming road is this one
/// (Junction::GetConnectingRoadIdFromIncomingRoadId), entered at their contact point: of two
/// connecting roads laid along the same way in opposite directions, the one leading out of
/// this road. A direct junction's connections also count the other way round, after all of
/// them (OpenDrive::CheckConnectedRoad adds a counter connection per connection whose linked
/// road links back to the junction: incoming road and linked road swapped, entered at the end
/// of the original incoming road that touches the junction, its successor end first); a
/// default junction's are `junction_connections::entering`'s, its counter connections after
/// its own (the ACC's `forward_delta` reads the same).
pub(crate) fn next_roads(net: &RoadNetwork, road: usize, exit: ContactPoint) -> Vec<RoadEnd> {
    let Some(r) = net.roads.get(road) else { return Vec::new() };
    match r.link_at(exit) {
        Some(l) if l.element_type == ElementType::Junction => {
            let Some(ji) = net.junction_index(&l.element_id) else { return Vec::new() };
            let Some(j) = net.junctions.get(ji) else { return Vec::new() };
            if j.kind != JunctionType::Direct {
                // A default junction's connections as esmini holds them, its counter connections
                // (OpenDrive::CheckJunctionConnection) after the junction's own.
                return super::junction_connections::entering(net, ji, road).into_iter().map(|c| RoadEnd { road: c.connecting, contact: c.contact }).collect();
            }
            let mut next: Vec<RoadEnd> = j
                .connections
                .iter()
                .filter(|c| c.incoming_road.as_deref() == Some(r.id.as_str()))
                .filter_map(|c| Some(RoadEnd { road: net.road_index(c.target_road()?)?, contact: c.contact_point.unwrap_or(ContactPoint::Start) }))
                .collect();
            let touches =
                |inc: &opendrive::Road, end: ContactPoint| inc.link_at(end).is_some_and(|l| l.element_type == ElementType::Junction && l.element_id == j.id);
            for c in j.connections.iter().filter(|c| c.linked_road.as_deref() == Some(r.id.as_str())) {
                let Some(inc) = c.incoming_road.as_deref().and_then(|id| net.road_index(id)) else { continue };
                let Some(inc_road) = net.roads.get(inc) else { continue };
                let contact = if touches(inc_road, ContactPoint::End) {
                    ContactPoint::End
                } else if touches(inc_road, ContactPoint::Start) {
                    ContactPoint::Start
                } else {
                    continue;
                };
                let end = RoadEnd { road: inc, contact };
                if !next.contains(&end) {
                    next.push(end);
                }
            }
            next
        }
        _ => net.roads_at(road, exit),
    }
}

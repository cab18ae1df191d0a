//! Topology: which road ends meet, and which lanes continue into which, across lane
//! sections, roads and junctions (default and direct). Directions are in s terms: the
//! lanes at the `End` of a lane are those that geometrically continue it at its larger s,
//! whatever way traffic flows.

use crate::model::junction::JunctionType;
use crate::model::road::{ContactPoint, ElementType, Road};
use crate::network::RoadNetwork;

/// One end of a road.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct RoadEnd {
    pub road: usize,
    pub contact: ContactPoint,
}

/// A lane of a lane section of a road.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct LaneRef {
    pub road: usize,
    pub section: usize,
    pub lane: i32,
}

/// Section index at one end of a road.
pub fn section_at_end(road: &Road, end: ContactPoint) -> usize {
    match end {
        ContactPoint::Start => road.section_index_at(0.0),
        ContactPoint::End => road.section_index_at(road.length),
    }
}

/// Lane ids linked from `lane` across its `end` (predecessors at Start, successors at End).
fn linked_ids(road: &Road, lane: LaneRef, end: ContactPoint) -> Vec<i32> {
    road.lane_sections
        .get(lane.section)
        .and_then(|s| s.lane(lane.lane))
        .map(|l| match end {
            ContactPoint::Start => l.predecessors.clone(),
            ContactPoint::End => l.successors.clone(),
        })
        .unwrap_or_default()
}

/// One junction-mediated link: from the lane `from` of the road at hand to lane `to` of `other`.
struct JunctionHop {
    other: RoadEnd,
    /// (lane of this road, lane of the other road)
    lanes: Vec<(i32, i32)>,
}

impl RoadNetwork {
    fn lane_exists(&self, r: LaneRef) -> bool {
        self.roads.get(r.road).and_then(|rd| rd.lane_sections.get(r.section)).and_then(|s| s.lane(r.lane)).is_some()
    }

    /// Whether the link of `other` at `other_end` names `road` and (if given) `end`.
    fn links_back(&self, other: usize, other_end: ContactPoint, road: usize, end: ContactPoint) -> bool {
        let (Some(o), Some(r)) = (self.roads.get(other), self.roads.get(road)) else { return false };
        match o.link_at(other_end) {
            Some(l) if l.element_type == ElementType::Road && l.element_id == r.id => !matches!(l.contact_point, Some(c) if c != end),
            Some(l) if l.element_type == ElementType::Road => false,
            _ => true,
        }
    }

    /// Roads reached through the junction at `end` of `road`, with lane pairs.
    fn junction_hops(&self, road: usize, end: ContactPoint, junction_id: &str) -> Vec<JunctionHop> {
        let mut hops = Vec::new();
        let Some(r) = self.roads.get(road) else { return hops };
        let Some(j) = self.junction(junction_id) else { return hops };
        // (a) connections that name this road as incoming.
        for c in j.connections.iter().filter(|c| c.incoming_road.as_deref() == Some(r.id.as_str())) {
            let Some(target) = c.target_road().and_then(|t| self.road_index(t)) else { continue };
            let cp = c.contact_point.unwrap_or(ContactPoint::Start);
            if j.kind != JunctionType::Direct && !self.links_back(target, cp, road, end) {
                continue;
            }
            hops.push(JunctionHop { other: RoadEnd { road: target, contact: cp }, lanes: c.lane_links.iter().map(|l| (l.from, l.to)).collect() });
        }
        // (b) direct junctions: connections that name this road as the linked road at `end`.
        if j.kind == JunctionType::Direct {
            for c in j.connections.iter().filter(|c| c.linked_road.as_deref() == Some(r.id.as_str())) {
                if c.contact_point.is_some_and(|cp| cp != end) {
                    continue;
                }
                let Some(inc) = c.incoming_road.as_deref().and_then(|t| self.road_index(t)) else { continue };
                let Some(inc_road) = self.roads.get(inc) else { continue };
                for inc_end in [ContactPoint::Start, ContactPoint::End] {
                    let hits = inc_road.link_at(inc_end).is_some_and(|l| l.element_type == ElementType::Junction && l.element_id == j.id);
                    if hits {
                        hops.push(JunctionHop { other: RoadEnd { road: inc, contact: inc_end }, lanes: c.lane_links.iter().map(|l| (l.to, l.from)).collect() });
                    }
                }
            }
        }
        // (c) connecting roads of the junction whose own link points at this road end.
        for (ci, cr) in self.roads.iter().enumerate() {
            if cr.junction.as_deref() != Some(j.id.as_str()) || ci == road {
                continue;
            }
            for cend in [ContactPoint::Start, ContactPoint::End] {
                let Some(l) = cr.link_at(cend) else { continue };
                if l.element_type != ElementType::Road || l.element_id != r.id || l.contact_point.is_some_and(|c| c != end) {
                    continue;
                }
                let sec = section_at_end(cr, cend);
                let mut lanes = Vec::new();
                if let Some(s) = cr.lane_sections.get(sec) {
                    for lane in s.lanes_left_to_right().filter(|l| l.id != 0) {
                        let ids = match cend {
                            ContactPoint::Start => &lane.predecessors,
                            ContactPoint::End => &lane.successors,
                        };
                        lanes.extend(ids.iter().map(|&mine| (mine, lane.id)));
                    }
                }
                hops.push(JunctionHop { other: RoadEnd { road: ci, contact: cend }, lanes });
            }
        }
        hops
    }

    /// Road ends that meet `end` of `road`, directly or through a junction; sorted, unique.
    pub fn roads_at(&self, road: usize, end: ContactPoint) -> Vec<RoadEnd> {
        let Some(r) = self.roads.get(road) else { return Vec::new() };
        let mut out = match r.link_at(end) {
            Some(l) if l.element_type == ElementType::Road => {
                self.road_index(&l.element_id).map(|o| vec![RoadEnd { road: o, contact: l.contact_point.unwrap_or(ContactPoint::Start) }]).unwrap_or_default()
            }
            Some(l) => self.junction_hops(road, end, &l.element_id).into_iter().map(|h| h.other).collect(),
            None => Vec::new(),
        };
        out.sort();
        out.dedup();
        out
    }

    /// Lanes that continue `lane` across its `end` (Start = smaller s, End = larger s):
    /// the neighbouring lane section of the same road, else the linked road, else every
    /// road the junction leads to. Sorted and unique; only lanes that exist are returned.
    pub fn lanes_across(&self, lane: LaneRef, end: ContactPoint) -> Vec<LaneRef> {
        let Some(r) = self.roads.get(lane.road) else { return Vec::new() };
        let last = r.lane_sections.len().saturating_sub(1);
        let inner = match end {
            ContactPoint::Start if lane.section > 0 => Some(lane.section - 1),
            ContactPoint::End if lane.section < last => Some(lane.section + 1),
            _ => None,
        };
        let mut out = Vec::new();
        if let Some(sec) = inner {
            out = linked_ids(r, lane, end).into_iter().map(|id| LaneRef { road: lane.road, section: sec, lane: id }).collect();
        } else {
            match r.link_at(end) {
                Some(l) if l.element_type == ElementType::Road => {
                    if let Some(o) = self.road_index(&l.element_id) {
                        let cp = l.contact_point.unwrap_or(ContactPoint::Start);
                        let sec = self.roads.get(o).map_or(0, |or| section_at_end(or, cp));
                        out = linked_ids(r, lane, end).into_iter().map(|id| LaneRef { road: o, section: sec, lane: id }).collect();
                    }
                }
                Some(l) => {
                    for hop in self.junction_hops(lane.road, end, &l.element_id) {
                        let sec = self.roads.get(hop.other.road).map_or(0, |or| section_at_end(or, hop.other.contact));
                        for (mine, theirs) in hop.lanes {
                            if mine == lane.lane {
                                out.push(LaneRef { road: hop.other.road, section: sec, lane: theirs });
                            }
                        }
                    }
                }
                None => {}
            }
        }
        out.retain(|l| self.lane_exists(*l));
        out.sort();
        out.dedup();
        out
    }

    /// Lanes continuing `lane` at its larger-s end.
    pub fn lane_successors(&self, lane: LaneRef) -> Vec<LaneRef> {
        self.lanes_across(lane, ContactPoint::End)
    }

    /// Lanes continuing `lane` at its smaller-s end.
    pub fn lane_predecessors(&self, lane: LaneRef) -> Vec<LaneRef> {
        self.lanes_across(lane, ContactPoint::Start)
    }
}

//! Dijkstra over lanes of lane sections, one leg (waypoint to waypoint) at a time.
//!
//! A state is a lane of a lane section driven in one direction, entered at an s: the
//! section boundary, or the leg's start s for the start lane and lanes reached from it by
//! lane changes. Edges continue into linked lanes at the section's far end or change to an
//! adjacent lane of the same direction. The goal is reached when the target s lies ahead
//! in the target lane.

use crate::cost;
use crate::waypoint::Strategy;
use opendrive::{drives_along_s, ContactPoint, LaneRef, LaneType, RoadNetwork};
use std::cmp::Ordering;
use std::collections::{BTreeMap, BinaryHeap};

/// Slack for "the target lies ahead" (m).
const AHEAD_EPS: f64 = 1e-6;
/// Most states expanded per leg (hostile networks).
const MAX_EXPANSIONS: usize = 2_000_000;

/// A lane section lane, driven along or against s; `fresh` when entered at the leg's start s.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Key {
    pub lane: LaneRef,
    pub along_s: bool,
    pub fresh: bool,
}

/// Where a leg starts or ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Point {
    pub lane: LaneRef,
    pub along_s: bool,
    pub s: f64,
}

/// How strictly the search follows the map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Rules {
    /// Intermediate lanes must be driven in their driving direction.
    pub obey_direction: bool,
    /// The goal must be the target's lane and direction (else any lane of its section).
    pub exact_target: bool,
    /// The target's road may be entered from a road end it meets whether or not the lane
    /// driven continues into it (esmini's RoadPath::Calculate takes a linked road, or a
    /// junction's connecting road, that is the target road as reached before
    /// RoadPath::CheckRoad looks at lanes); it is entered on the target's lane.
    pub lane_free_target_entry: bool,
}

/// One step of a found path: the state, its entry s, and whether it was reached by a lane change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Step {
    pub key: Key,
    pub entry_s: f64,
    pub lane_change: bool,
}

#[derive(Debug, Clone, Copy)]
struct Label {
    cost: f64,
    entry_s: f64,
    prev: Option<Key>,
    lane_change: bool,
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Queued {
    cost: f64,
    key: Key,
    /// Some(s) for the goal: reached at s in this state.
    goal: Option<f64>,
}
impl Eq for Queued {}
impl Ord for Queued {
    fn cmp(&self, o: &Self) -> Ordering {
        // Min-heap on cost; ties broken by key, goals first, for determinism.
        o.cost.total_cmp(&self.cost).then_with(|| o.goal.is_none().cmp(&self.goal.is_none())).then_with(|| o.key.cmp(&self.key))
    }
}
impl PartialOrd for Queued {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

pub(crate) struct Search<'a> {
    pub net: &'a RoadNetwork,
    pub strategy: Strategy,
    pub rules: Rules,
    /// A lane type the route may use besides the drivable ones (the start lane's).
    pub extra_kind: Option<LaneType>,
}

impl Search<'_> {
    fn section_range(&self, l: LaneRef) -> Option<(f64, f64)> {
        self.net.roads.get(l.road)?.section_range(l.section)
    }

    fn usable(&self, l: LaneRef, along_s: bool) -> bool {
        let Some(r) = self.net.roads.get(l.road) else { return false };
        let Some(lane) = r.lane_sections.get(l.section).and_then(|s| s.lane(l.lane)) else { return false };
        if l.lane == 0 || !(cost::is_drivable(lane.kind) || Some(lane.kind) == self.extra_kind) {
            return false;
        }
        !self.rules.obey_direction || lane.kind == LaneType::Bidirectional || drives_along_s(r.rule, l.lane) == along_s
    }

    /// Direction of travel on `next` after leaving `from` at its `end`.
    fn entry_direction(&self, from: LaneRef, end: ContactPoint, next: LaneRef, along_s: bool) -> bool {
        if next.road == from.road {
            return along_s;
        }
        let contacts: Vec<ContactPoint> = self.net.roads_at(from.road, end).into_iter().filter(|e| e.road == next.road).map(|e| e.contact).collect();
        match contacts.as_slice() {
            [c] => *c == ContactPoint::Start,
            _ => self.net.roads.get(next.road).is_some_and(|r| drives_along_s(r.rule, next.lane)),
        }
    }

    fn is_goal(&self, key: Key, target: &Point) -> bool {
        if key.lane.road != target.lane.road || key.lane.section != target.lane.section {
            return false;
        }
        !self.rules.exact_target || (key.lane.lane == target.lane.lane && key.along_s == target.along_s)
    }

    /// Cheapest steps from `start` to `target`, with the s at which the target is reached.
    pub(crate) fn run(&self, start: Point, target: &Point) -> Option<(Vec<Step>, f64)> {
        let mut labels: BTreeMap<Key, Label> = BTreeMap::new();
        let mut done: BTreeMap<Key, ()> = BTreeMap::new();
        let mut heap = BinaryHeap::new();
        let k0 = Key { lane: start.lane, along_s: start.along_s, fresh: true };
        labels.insert(k0, Label { cost: 0.0, entry_s: start.s, prev: None, lane_change: false });
        heap.push(Queued { cost: 0.0, key: k0, goal: None });
        let mut expansions = 0usize;
        while let Some(q) = heap.pop() {
            if let Some(s_goal) = q.goal {
                return Some((self.unwind(&labels, q.key), s_goal));
            }
            if done.insert(q.key, ()).is_some() {
                continue;
            }
            expansions += 1;
            if expansions > MAX_EXPANSIONS {
                return None;
            }
            let Some(label) = labels.get(&q.key).copied() else { continue };
            let key = q.key;
            let Some((s0, s1)) = self.section_range(key.lane) else { continue };
            let (sign, exit_s) = if key.along_s { (1.0, s1) } else { (-1.0, s0) };
            // Goal: the target s ahead of the entry in this state.
            if self.is_goal(key, target) && sign * (target.s - label.entry_s) >= -AHEAD_EPS {
                let d = (target.s - label.entry_s).abs();
                let c = label.cost + cost::drive(self.strategy, self.net, key.lane.road, key.lane.section, key.lane.lane, d);
                heap.push(Queued { cost: c, key, goal: Some(target.s) });
            }
            let relax = |heap: &mut BinaryHeap<Queued>, labels: &mut BTreeMap<Key, Label>, next: Key, cost: f64, entry_s: f64, lane_change: bool| {
                if done.contains_key(&next) {
                    return;
                }
                if labels.get(&next).is_none_or(|l| cost < l.cost) {
                    labels.insert(next, Label { cost, entry_s, prev: Some(key), lane_change });
                    heap.push(Queued { cost, key: next, goal: None });
                }
            };
            // Lane changes to adjacent lanes on the same side, same direction.
            for step in [-1, 1] {
                let id = key.lane.lane + step;
                if id == 0 || id.signum() != key.lane.lane.signum() {
                    continue;
                }
                let l = LaneRef { lane: id, ..key.lane };
                if self.usable(l, key.along_s) {
                    let c = label.cost + cost::lane_change(self.strategy, self.net, l.road, l.section, l.lane);
                    relax(&mut heap, &mut labels, Key { lane: l, along_s: key.along_s, fresh: key.fresh }, c, label.entry_s, true);
                }
            }
            // Drive to the far end of the section and into the linked lanes.
            let d = (exit_s - label.entry_s).abs();
            let base = label.cost + cost::drive(self.strategy, self.net, key.lane.road, key.lane.section, key.lane.lane, d);
            let end = if key.along_s { ContactPoint::End } else { ContactPoint::Start };
            for next in self.net.lanes_across(key.lane, end) {
                let along = self.entry_direction(key.lane, end, next, key.along_s);
                if !self.usable(next, along) {
                    continue;
                }
                let Some((n0, n1)) = self.section_range(next) else { continue };
                let entry = if along { n0 } else { n1 };
                let c = base + cost::transition(self.strategy, self.net, key.lane.road, next.road);
                relax(&mut heap, &mut labels, Key { lane: next, along_s: along, fresh: false }, c, entry, false);
            }
            if self.rules.lane_free_target_entry {
                for (next, along) in self.target_entries(key.lane, end, target) {
                    let Some((n0, n1)) = self.section_range(next) else { continue };
                    let entry = if along { n0 } else { n1 };
                    let c = base + cost::transition(self.strategy, self.net, key.lane.road, next.road);
                    relax(&mut heap, &mut labels, Key { lane: next, along_s: along, fresh: false }, c, entry, false);
                }
            }
        }
        None
    }

    /// The target's lane where the target's road meets `end` of `lane`'s road, and whether it
    /// is then driven along s (entered at its start), for `Rules::lane_free_target_entry`:
    /// only from a road's last lane section on that end, as a road link or a junction joins
    /// road ends.
    fn target_entries(&self, lane: LaneRef, end: ContactPoint, target: &Point) -> Vec<(LaneRef, bool)> {
        let Some(r) = self.net.roads.get(lane.road) else { return Vec::new() };
        let at_end = match end {
            ContactPoint::Start => lane.section == 0,
            ContactPoint::End => lane.section + 1 >= r.lane_sections.len(),
        };
        if !at_end || target.lane.road == lane.road {
            return Vec::new();
        }
        let Some(tr) = self.net.roads.get(target.lane.road) else { return Vec::new() };
        self.net
            .roads_at(lane.road, end)
            .into_iter()
            .filter(|e| e.road == target.lane.road)
            .filter_map(|e| {
                let section = opendrive::section_at_end(tr, e.contact);
                let next = LaneRef { road: e.road, section, lane: target.lane.lane };
                tr.lane_sections.get(section).and_then(|sec| sec.lane(next.lane)).map(|_| (next, e.contact == ContactPoint::Start))
            })
            .collect()
    }

    fn unwind(&self, labels: &BTreeMap<Key, Label>, last: Key) -> Vec<Step> {
        let mut out = Vec::new();
        let mut at = Some(last);
        while let Some(k) = at {
            let Some(l) = labels.get(&k) else { break };
            out.push(Step { key: k, entry_s: l.entry_s, lane_change: l.lane_change });
            at = l.prev;
            if out.len() > labels.len() {
                break;
            }
        }
        out.reverse();
        out
    }
}

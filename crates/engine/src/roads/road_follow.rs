//! Moving a lane position along its lane: s advances by the travelled distance scaled to the
//! reference line (lanes off the reference line on curves are longer or shorter), across lane
//! sections, linked roads and junctions.
//!
//! Junction rule without a route: the continuation whose heading at its far end turns least from
//! the heading at entry (the straightest way through), ties broken by road index then lane id.
//! esmini starts every entity with junction selector angle 0 (straight on), which this matches
//! for the first junction an entity meets.

use super::lane_geometry::lane_borders;
use super::lane_position::LanePos;
use opendrive::{ContactPoint, LaneRef, RoadNetwork};

/// What happened during a move.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MoveStatus {
    Ok,
    /// No lane continues the entity's lane: it stopped at the road end.
    EndOfRoad,
}

/// Most road changes one move may cross (guards against zero-length road loops).
const MAX_HOPS: usize = 16;

/// Move `pos` by `dist` metres along the direction it faces (negative: backwards).
pub fn move_along_s(net: &RoadNetwork, pos: &mut LanePos, dist: f64) -> MoveStatus {
    move_along_route(net, pos, dist, None)
}

/// [`move_along_s`], taking at junctions the road an assigned route continues on.
pub fn move_along_route(net: &RoadNetwork, pos: &mut LanePos, dist: f64, route: Option<&routing::Route>) -> MoveStatus {
    let Some(road) = net.roads.get(pos.road) else { return MoveStatus::EndOfRoad };
    let s0 = pos.s.clamp(0.0, road.length);
    let p = super::pose_memo::reference_pose(road, s0);
    let t = super::pose_memo::lane_borders_at(road, pos.lane_id, s0).map_or(0.0, |(a, b)| 0.5 * (a + b)) + pos.offset;
    // Distance along the lane to distance along the reference line.
    let scale = (1.0 - p.curvature * t).max(0.1);
    let ds = pos.dir * dist / scale;
    let mut s = s0 + ds;
    let section_before = road.section_index_at(s0);
    let road_before = pos.road;
    for _ in 0..MAX_HOPS {
        let Some(road) = net.roads.get(pos.road) else { return MoveStatus::EndOfRoad };
        if s >= 0.0 && s <= road.length {
            pos.s = s;
            let section_now = road.section_index_at(s);
            if section_now != section_before && pos.road == road_before {
                follow_section_change(net, pos, section_before, section_now);
            }
            return MoveStatus::Ok;
        }
        let (end, overshoot) = if s > road.length { (ContactPoint::End, s - road.length) } else { (ContactPoint::Start, -s) };
        let section = opendrive::section_at_end(road, end);
        let here = LaneRef { road: pos.road, section, lane: pos.lane_id };
        let heading_in = road.reference_pose(if end == ContactPoint::End { road.length } else { 0.0 }).hdg
            + if end == ContactPoint::End { 0.0 } else { std::f64::consts::PI };
        let routed = route.and_then(|r| routed_continuation(net, r, here, end));
        let Some((next, contact)) = routed.or_else(|| choose_continuation(net, here, end, heading_in)) else {
            pos.s = s.clamp(0.0, road.length);
            return MoveStatus::EndOfRoad;
        };
        let Some(next_road) = net.roads.get(next.road) else { return MoveStatus::EndOfRoad };
        let flips = (end == ContactPoint::End) == (contact == ContactPoint::End);
        pos.road = next.road;
        pos.lane_id = next.lane;
        if flips {
            pos.dir = -pos.dir;
            pos.offset = -pos.offset;
        }
        s = match contact {
            ContactPoint::Start => overshoot,
            ContactPoint::End => next_road.length - overshoot,
        };
        if s >= 0.0 && s <= next_road.length {
            pos.s = s;
            return MoveStatus::Ok;
        }
    }
    MoveStatus::Ok
}

/// The lane continuing `here` across its `end` onto the road the route takes next, if the
/// route passes this road in this direction and a lane leads there.
fn routed_continuation(net: &RoadNetwork, route: &routing::Route, here: LaneRef, end: ContactPoint) -> Option<(LaneRef, ContactPoint)> {
    let next = route.next_road_after(here.road, end == ContactPoint::End)?;
    let cands = net.lanes_across(here, end);
    let on_road = |c: &&LaneRef| c.road == next.road;
    // The route's own lane when it is reachable, else the lane link's lane on that road.
    let pick = cands.iter().filter(on_road).find(|c| c.lane == next.lane).or_else(|| cands.iter().find(on_road))?;
    let contact = if pick.road == here.road {
        if end == ContactPoint::End { ContactPoint::Start } else { ContactPoint::End }
    } else {
        next.contact
    };
    Some((*pick, contact))
}

/// The lane continuing `here` across its `end`, and the contact point on that lane's road.
fn choose_continuation(net: &RoadNetwork, here: LaneRef, end: ContactPoint, heading_in: f64) -> Option<(LaneRef, ContactPoint)> {
    let cands = net.lanes_across(here, end);
    if cands.is_empty() {
        return None;
    }
    let ends = net.roads_at(here.road, end);
    let contact_of = |road: usize| -> ContactPoint {
        let mut found: Option<ContactPoint> = None;
        for e in &ends {
            if e.road == road {
                found = Some(e.contact);
                break;
            }
        }
        found.unwrap_or(ContactPoint::Start)
    };
    let mut best: Option<(f64, LaneRef, ContactPoint)> = None;
    for c in cands {
        // Only lanes leading away in the same travel sense (lanes_across gives lane links, which
        // are directional already).
        let contact = if c.road == here.road { if end == ContactPoint::End { ContactPoint::Start } else { ContactPoint::End } } else { contact_of(c.road) };
        let Some(r) = net.roads.get(c.road) else { continue };
        let far_heading = match contact {
            ContactPoint::Start => r.reference_pose(r.length).hdg,
            ContactPoint::End => r.reference_pose(0.0).hdg + std::f64::consts::PI,
        };
        let turn = wrap(far_heading - heading_in).abs();
        let better = match &best {
            None => true,
            Some((bt, b, _)) => turn < bt - 1e-9 || ((turn - bt).abs() <= 1e-9 && (c.road, c.lane.abs()) < (b.road, b.lane.abs())),
        };
        if better {
            best = Some((turn, c, contact));
        }
    }
    best.map(|(_, l, c)| (l, c))
}

/// Keep the lane across a lane-section boundary inside one road, following lane links.
fn follow_section_change(net: &RoadNetwork, pos: &mut LanePos, before: usize, now: usize) {
    let Some(road) = net.roads.get(pos.road) else { return };
    let end = if now > before { ContactPoint::End } else { ContactPoint::Start };
    let next = net.lanes_across(LaneRef { road: pos.road, section: before, lane: pos.lane_id }, end);
    if let Some(n) = next.iter().find(|n| n.road == pos.road) {
        pos.lane_id = n.lane;
        return;
    }
    if lane_borders(road, now, pos.lane_id, pos.s).is_none() {
        // No link and the lane id is gone: take the lane of the same side nearest the centre.
        if let Some(sec) = road.lane_sections.get(now) {
            let side = if pos.lane_id > 0 { &sec.left } else { &sec.right };
            if let Some(l) = side.last() {
                pos.lane_id = l.id;
            }
        }
    }
}

/// Angle wrapped to (-π, π].
pub fn wrap(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let mut x = (a + std::f64::consts::PI) % two_pi;
    if x < 0.0 {
        x += two_pi;
    }
    x - std::f64::consts::PI
}

//! Moving a lane position along its lane: s advances by the travelled distance scaled to the
//! reference line (lanes off the reference line on curves are longer or shorter), across lane
//! sections, linked roads and junctions.
//!
//! Junction rule without a route, as esmini's `Position::MoveToConnectingRoad` with junction
//! selector angle 0 (straight on, which is what esmini 3.6's default controller uses): the
//! continuations are visited in the junction's connection order and the one whose heading at its
//! far end turns least from the heading the entity drives in wins; a later one that turns less
//! wins outright, one that turns as much (within 1e-10 rad, e.g. the two ±90° arms of a T) wins
//! when a coin drawn from esmini's global generator says 1 (`esmini_random`). Only the default
//! controller's move draws (`move_along_route_drawing`); probes and other moves keep the earlier
//! arm at a tie, so they never disturb the generator's sequence.

use super::lane_geometry::lane_borders;
use super::lane_position::LanePos;
use crate::esmini_random::EsminiRandom;
use opendrive::{ContactPoint, ElementType, LaneRef, RoadNetwork};

/// What happened during a move.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum MoveStatus {
    Ok,
    /// No lane continues the entity's lane: it stopped at the road end.
    EndOfRoad,
}

/// Whether `lp` is at the end of its road in the direction it faces, with no road beyond
/// (esmini's POS_STATUS_END_OF_ROAD after Position::SetInertiaPos).
pub(crate) fn at_dead_end(net: &RoadNetwork, lp: &LanePos) -> bool {
    const SMALL_NUMBER: f64 = 1e-6;
    net.roads.get(lp.road).is_some_and(|r| {
        let end = if lp.dir > 0.0 { lp.s >= r.length - SMALL_NUMBER } else { lp.s <= SMALL_NUMBER };
        end && if lp.dir > 0.0 { r.successor.is_none() } else { r.predecessor.is_none() }
    })
}

/// Most road changes one move may cross (guards against zero-length road loops).
const MAX_HOPS: usize = 16;

/// esmini's SMALL_NUMBER: junction arms turning within this of each other are a tie, rad.
const TIE: f64 = 1e-10;

/// Move `pos` by `dist` metres along the direction it faces (negative: backwards).
pub(crate) fn move_along_s(net: &RoadNetwork, pos: &mut LanePos, dist: f64) -> MoveStatus {
    move_along_route(net, pos, dist, None)
}

/// [`move_along_s`], taking at junctions the road an assigned route continues on.
pub(crate) fn move_along_route(net: &RoadNetwork, pos: &mut LanePos, dist: f64, route: Option<&routing::Route>) -> MoveStatus {
    move_along(net, pos, dist, route, None)
}

/// [`move_along_route`] for an entity's own move by the default controller: a junction tie is
/// broken by a draw from esmini's generator, as esmini does.
pub(crate) fn move_along_route_drawing(
    net: &RoadNetwork,
    pos: &mut LanePos,
    dist: f64,
    route: Option<&routing::Route>,
    random: &mut EsminiRandom,
) -> MoveStatus {
    move_along(net, pos, dist, route, Some(random))
}

fn move_along(net: &RoadNetwork, pos: &mut LanePos, dist: f64, route: Option<&routing::Route>, mut random: Option<&mut EsminiRandom>) -> MoveStatus {
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
    // Where the entity is when it leaves a road: esmini measures the turn of each junction arm
    // from the road heading there (the start of the move, then the end of the road it came in by).
    let mut s_here = s0;
    for _ in 0..MAX_HOPS {
        let Some(road) = net.roads.get(pos.road) else { return MoveStatus::EndOfRoad };
        if s >= 0.0 && s <= road.length {
            pos.s = s;
            let section_now = road.section_index_at(s);
            if section_now != section_before && pos.road == road_before {
                follow_section_change(net, pos, section_before, section_now);
            }
            super::zero_width::leave_zero_width_lane_in(net, pos, section_now);
            return MoveStatus::Ok;
        }
        let (end, overshoot) = if s > road.length { (ContactPoint::End, s - road.length) } else { (ContactPoint::Start, -s) };
        let section = opendrive::section_at_end(road, end);
        let here = LaneRef { road: pos.road, section, lane: pos.lane_id };
        let facing_back = if pos.dir < 0.0 { std::f64::consts::PI } else { 0.0 };
        let heading_in = super::pose_memo::reference_pose(road, s_here.clamp(0.0, road.length)).hdg + facing_back;
        let routed = route.and_then(|r| routed_continuation(net, r, here, end));
        let Some((next, contact)) = routed.or_else(|| choose_continuation(net, here, end, heading_in, random.as_deref_mut())) else {
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
        s_here = match contact {
            ContactPoint::Start => 0.0,
            ContactPoint::End => next_road.length,
        };
        s = match contact {
            ContactPoint::Start => overshoot,
            ContactPoint::End => next_road.length - overshoot,
        };
        if s >= 0.0 && s <= next_road.length {
            pos.s = s;
            super::zero_width::leave_zero_width_lane(net, pos);
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
        if end == ContactPoint::End {
            ContactPoint::Start
        } else {
            ContactPoint::End
        }
    } else {
        next.contact
    };
    Some((*pick, contact))
}

/// The lane continuing `here` across its `end`, and the contact point on that lane's road.
/// `heading_in`: the road heading the entity drives in where it is.
fn choose_continuation(
    net: &RoadNetwork,
    here: LaneRef,
    end: ContactPoint,
    heading_in: f64,
    mut random: Option<&mut EsminiRandom>,
) -> Option<(LaneRef, ContactPoint)> {
    let mut cands = net.lanes_across(here, end);
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
    let junction = junction_at(net, here, end);
    if let Some(j) = junction {
        order_by_connections(net, here, j, &mut cands);
    }
    let mut best: Option<(f64, LaneRef, ContactPoint)> = None;
    for c in cands {
        // Only lanes leading away in the same travel sense (lanes_across gives lane links, which
        // are directional already).
        let contact = if c.road == here.road {
            if end == ContactPoint::End {
                ContactPoint::Start
            } else {
                ContactPoint::End
            }
        } else {
            contact_of(c.road)
        };
        let Some(r) = net.roads.get(c.road) else { continue };
        let far_heading = match contact {
            ContactPoint::Start => r.reference_pose(r.length).hdg,
            ContactPoint::End => r.reference_pose(0.0).hdg + std::f64::consts::PI,
        };
        let turn = wrap(far_heading - heading_in).abs();
        let better = match &best {
            None => true,
            // esmini: a later arm that turns less wins; one that turns as much wins on a coin.
            Some((bt, _, _)) if junction.is_some() => {
                turn < *bt || ((turn - bt).abs() < TIE && random.as_deref_mut().is_some_and(|g| g.number_between(0, 1) == 1))
            }
            Some((bt, b, _)) => turn < bt - 1e-9 || ((turn - bt).abs() <= 1e-9 && (c.road, c.lane.abs()) < (b.road, b.lane.abs())),
        };
        if better {
            best = Some((turn, c, contact));
        }
    }
    best.map(|(_, l, c)| (l, c))
}

/// The junction `here` leaves into across `end`, when there is one (not a lane-section change
/// inside the road).
fn junction_at(net: &RoadNetwork, here: LaneRef, end: ContactPoint) -> Option<&opendrive::Junction> {
    let road = net.roads.get(here.road)?;
    let last = road.lane_sections.len().saturating_sub(1);
    let inner = match end {
        ContactPoint::Start => here.section > 0,
        ContactPoint::End => here.section < last,
    };
    if inner {
        return None;
    }
    let link = road.link_at(end)?;
    if link.element_type != ElementType::Junction {
        return None;
    }
    net.junction(&link.element_id)
}

/// Sort junction arms the way esmini visits them: by the junction's connections from this road
/// (document order), lane links in order; arms no connection names come last, by road.
fn order_by_connections(net: &RoadNetwork, here: LaneRef, junction: &opendrive::Junction, cands: &mut [LaneRef]) {
    let Some(road) = net.roads.get(here.road) else { return };
    let rank = |c: &LaneRef| -> usize {
        let Some(target) = net.roads.get(c.road) else { return usize::MAX };
        let mut k = 0usize;
        for conn in junction.connections.iter().filter(|x| x.incoming_road.as_deref() == Some(road.id.as_str())) {
            for link in conn.lane_links.iter().filter(|l| l.from == here.lane) {
                if conn.target_road() == Some(target.id.as_str()) && link.to == c.lane {
                    return k;
                }
                k += 1;
            }
        }
        usize::MAX
    };
    // Stable: equal ranks (unnamed arms) keep lanes_across's road order.
    cands.sort_by_key(|c| rank(c));
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
pub(crate) fn wrap(a: f64) -> f64 {
    let two_pi = 2.0 * std::f64::consts::PI;
    let mut x = (a + std::f64::consts::PI) % two_pi;
    if x < 0.0 {
        x += two_pi;
    }
    x - std::f64::consts::PI
}

//! Moving a lane position along its lane: s advances by the travelled distance scaled to the
//! reference line (lanes off the reference line on curves are longer or shorter), across lane
//! sections, linked roads and junctions.
//!
//! Junction rule without a route, as esmini's `Position::MoveToConnectingRoad` with junction
//! selector angle 0 (straight on, which is what esmini 3.6's default controller uses): the
//! continuations are visited in the junction's connection order and the one whose heading at its
//! far end turns least from the driving direction of the entity's lane wins (whichever way the
//! entity faces or moves); a later one that turns less
//! wins outright, one that turns as much (within 1e-10 rad, e.g. the two ±90° arms of a T) wins
//! when a coin drawn from esmini's global generator says 1 (`esmini_random`). The default
//! controller's move draws (`move_along_route_drawing`), and so do the looming controller's
//! lane-centre probes (Position::GetProbeInfo moves a copy of the position the same way); other
//! moves keep the earlier arm at a tie, so they never disturb the generator's sequence.
//! A move with junction selector angle −1 (Position::MoveAlongS's two-argument form, which a
//! rigid LongitudinalDistanceAction and a LaneChangeAction's step — LatLaneChangeAction::Step —
//! use) draws the arm itself, uniformly among the lane's connections in esmini's order, straight
//! arm or not (`move_along_s_drawn`).

use super::lane_geometry::lane_borders;
use super::lane_position::LanePos;
use crate::angles::wrap;
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
    use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;
    net.roads.get(lp.road).is_some_and(|r| {
        let end = if lp.dir > 0.0 { lp.s >= r.length - SMALL_NUMBER } else { lp.s <= SMALL_NUMBER };
        end && if lp.dir > 0.0 { r.successor.is_none() } else { r.predecessor.is_none() }
    })
}

/// Position::MoveAlongS's last word on POS_STATUS_END_OF_ROAD after a move that stays on a
/// road: set when the position ends within esmini's SMALL_NUMBER of either end of its road and
/// the road has no link at that end, whichever way the entity moved (a move of 0 m, or a
/// creep back by a rounding error, keeps a car at a dead end flagged), cleared otherwise.
pub(crate) fn at_unlinked_road_end(net: &RoadNetwork, lp: &LanePos) -> bool {
    use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL;
    net.roads.get(lp.road).is_some_and(|r| (lp.s < SMALL && r.predecessor.is_none()) || (lp.s > r.length - SMALL && r.successor.is_none()))
}

/// Most road changes one move may cross: esmini's Position::MoveAlongS follows at most
/// `max_links` (8) links, and a move that would land past the eighth stays where it entered the
/// eighth road (it is also what bounds a loop of zero-length roads).
const MAX_HOPS: usize = 8;

/// esmini's SMALL_NUMBER (CommonMini.hpp: 1e-6): junction arms turning within this of each
/// other are a tie, rad (Position::MoveToConnectingRoad compares `heading_diff` with it). Maps
/// whose headings are written to eight decimals (π/2 as 1.570796335) give arms that differ by
/// ~1e-8 rad: a tie for esmini, decided by its draw.
const TIE: f64 = 1e-6;

/// How a move without a route picks among a junction's arms.
enum Arms<'r> {
    /// The arm that turns least (junction selector angle 0); a tie on esmini's coin when a
    /// generator is given, else the earlier arm.
    Straightest(Option<&'r mut EsminiRandom>),
    /// Any arm, drawn from esmini's generator: Position::MoveToConnectingRoad with a junction
    /// selector angle below 0 takes connection GetNumberBetween(0, n − 1) of the lane's n.
    Drawn(&'r mut EsminiRandom),
}

/// Move `pos` by `dist` metres along the direction it faces (negative: backwards).
pub(crate) fn move_along_s(net: &RoadNetwork, pos: &mut LanePos, dist: f64) -> MoveStatus {
    move_along_route(net, pos, dist, None)
}

/// [`move_along_s`], taking at junctions the road an assigned route continues on.
pub(crate) fn move_along_route(net: &RoadNetwork, pos: &mut LanePos, dist: f64, route: Option<&routing::Route>) -> MoveStatus {
    move_along(net, pos, dist, route, Arms::Straightest(None), false, true)
}

/// [`move_along_route`] as esmini's `Position::MoveAlongS(ds)` (junction selector angle −1):
/// without a route, a junction's arm is drawn from esmini's generator.
pub(crate) fn move_along_s_drawn(net: &RoadNetwork, pos: &mut LanePos, dist: f64, route: Option<&routing::Route>, random: &mut EsminiRandom) -> MoveStatus {
    move_along(net, pos, dist, route, Arms::Drawn(random), false, true)
}

/// Move `pos` by `ds` in road s (not a distance along its lane) in the direction it faces,
/// taking at junctions the road `route` continues on: esmini's Position::MoveAlongS with
/// actualDistance false, as a relative position moves a copy of its reference entity.
/// A junction tie is broken by a draw from `random` when given (esmini's seeded draw), else
/// the first of the tied arms.
pub(crate) fn move_along_road_s(
    net: &RoadNetwork,
    pos: &mut LanePos,
    ds: f64,
    route: Option<&routing::Route>,
    random: Option<&mut EsminiRandom>,
) -> MoveStatus {
    move_along(net, pos, ds, route, Arms::Straightest(random), false, false)
}

/// [`move_along_route`] for an entity's own move by the default controller: a junction tie is
/// broken by a draw from esmini's generator, as esmini does; `sidewalks`: the entity is a
/// pedestrian, whose lane, when it narrows to nothing, may give way to a sidewalk.
pub(crate) fn move_along_route_drawing(
    net: &RoadNetwork,
    pos: &mut LanePos,
    dist: f64,
    route: Option<&routing::Route>,
    random: &mut EsminiRandom,
    sidewalks: bool,
) -> MoveStatus {
    move_along(net, pos, dist, route, Arms::Straightest(Some(random)), sidewalks, true)
}

/// `along_lane`: `dist` is a distance along the lane (scaled to road s on curves), else road s.
fn move_along(
    net: &RoadNetwork,
    pos: &mut LanePos,
    dist: f64,
    route: Option<&routing::Route>,
    mut arms: Arms,
    sidewalks: bool,
    along_lane: bool,
) -> MoveStatus {
    // Distance along the lane to distance along the reference line (may first relocate `pos`).
    let scale = if along_lane { lane_step_scale(net, pos, sidewalks) } else { 1.0 };
    let Some(road) = net.roads.get(pos.road) else { return MoveStatus::EndOfRoad };
    let s0 = pos.s.clamp(0.0, road.length);
    let ds = pos.dir * if along_lane { dist * scale } else { dist };
    // A standing entity exactly at the centre of curvature: 0·∞ (esmini's s turns NaN); stay.
    let ds = if ds.is_nan() { 0.0 } else { ds };
    let mut s = s0 + ds;
    let section_before = road.section_index_at(s0);
    let road_before = pos.road;
    // Where the entity is when it leaves a road: esmini measures the turn of each junction arm
    // from the road heading there (the start of the move, then the end of the road it came in by).
    let mut s_here = s0;
    let mut entered_section = section_before;
    for hop in 0..MAX_HOPS {
        let Some(road) = net.roads.get(pos.road) else { return MoveStatus::EndOfRoad };
        if s >= 0.0 && s <= road.length {
            pos.s = s;
            let section_now = road.section_index_at(s);
            if section_now != section_before && pos.road == road_before {
                follow_section_change(net, pos, section_before, section_now, sidewalks);
            }
            super::zero_width::leave_zero_width_lane_in(net, pos, section_now, sidewalks);
            return MoveStatus::Ok;
        }
        let (end, overshoot) = if s > road.length { (ContactPoint::End, s - road.length) } else { (ContactPoint::Start, -s) };
        let section = opendrive::section_at_end(road, end);
        // esmini's MoveAlongS sets the lane section to the end's without updating the lane
        // index (Position::lane_idx_, the place in the section's lanes sorted by id, most
        // positive first): MoveToConnectingRoad continues the lane at that index of the end
        // section, the index the lane had in the section the position was last set in (the
        // start of the move, or the contact end of a road entered on the way); no lane there:
        // no connection, the move stops at the road's end.
        let from_section = if hop == 0 { section_before } else { entered_section };
        let lane_id = match stale_index_lane(road, from_section, section, pos.lane_id) {
            Some(l) => l,
            None => {
                pos.s = s.clamp(0.0, road.length);
                return MoveStatus::EndOfRoad;
            }
        };
        let here = LaneRef { road: pos.road, section, lane: lane_id };
        // esmini measures from the heading of the lane's driving direction
        // (Position::GetHRoadInDrivingDirection), not from the way the entity faces or moves: a
        // car reversing into a junction picks the arm a car driving its lane would.
        let against_s = if opendrive::drives_along_s(road.rule, pos.lane_id) { 0.0 } else { std::f64::consts::PI };
        let heading_in = super::pose_memo::reference_pose(road, s_here.clamp(0.0, road.length)).hdg + against_s;
        let routed = route.and_then(|r| routed_continuation(net, r, here, end));
        let mut unlinked = false;
        let Some((next, contact)) = routed.or_else(|| choose_continuation(net, here, end, heading_in, &mut arms)).or_else(|| {
            unlinked = true;
            unlinked_lane_continuation(net, road, here, end, pos, sidewalks)
        }) else {
            pos.s = s.clamp(0.0, road.length);
            return MoveStatus::EndOfRoad;
        };
        let Some(next_road) = net.roads.get(next.road) else { return MoveStatus::EndOfRoad };
        pos.road = next.road;
        pos.lane_id = next.lane;
        if unlinked {
            // esmini's MoveToConnectingRoad returns from its closest-lane arm before it turns
            // the heading round at a start-to-start or end-to-end link: the entity keeps its
            // heading relative to the road (it may now face against the rest of this move, which
            // goes into the new road from the contact point), and its offset is reset ("Reset
            // lane offset when new move to new lane was enforced").
            pos.offset = 0.0;
        } else if (end == ContactPoint::End) == (contact == ContactPoint::End) {
            pos.dir = -pos.dir;
            pos.offset = -pos.offset;
        }
        s_here = match contact {
            ContactPoint::Start => 0.0,
            ContactPoint::End => next_road.length,
        };
        entered_section = opendrive::section_at_end(next_road, contact);
        s = match contact {
            ContactPoint::Start => overshoot,
            ContactPoint::End => next_road.length - overshoot,
        };
        // esmini checks where the rest of the move lands at the top of its next pass, and there
        // is none after the eighth link
        if hop + 1 < MAX_HOPS && s >= 0.0 && s <= next_road.length {
            pos.s = s;
            super::zero_width::leave_zero_width_lane(net, pos, sidewalks);
            return MoveStatus::Ok;
        }
    }
    // Past the last link: at the contact point of the road entered last (MoveAlongS's
    // SetLanePos there, `s_ + 0`), status OK.
    pos.s = s_here;
    MoveStatus::Ok
}

/// The lane at the index `lane_id` has among `from`'s lanes (sorted by id, most positive
/// first, as esmini's LaneSection keeps them) in section `to` of the same road: esmini's stale
/// `lane_idx_` after MoveAlongS switched the lane section to the road end's. `None`: the index
/// is past `to`'s lanes (GetLaneByIdx returns no lane).
fn stale_index_lane(road: &opendrive::Road, from: usize, to: usize, lane_id: i32) -> Option<i32> {
    if from == to {
        return Some(lane_id);
    }
    let (Some(a), Some(b)) = (road.lane_sections.get(from), road.lane_sections.get(to)) else { return Some(lane_id) };
    let Some(idx) = a.lanes_left_to_right().position(|l| l.id == lane_id) else { return Some(lane_id) };
    b.lanes_left_to_right().nth(idx).map(|l| l.id)
}

/// esmini's Position::DistanceToDS: a distance along a lane at lateral t is
/// `1 / (1 − curvature·t)` of road s, the factor unguarded (on curves only, |curvature| above
/// esmini's SMALL_NUMBER): a lane near a bend's centre of curvature moves fast in s. A position
/// at or past it (curvature·t above 1 − SMALL_NUMBER) is "probably closer to another road
/// segment" and is first located afresh from its world point (XYZ2TrackPos from its current
/// road, on the nearest lane of the types it snaps to; SetHeadingRelative keeps the way it
/// faces); where the factor is then still infinite or negative the move jumps to a road end.
fn lane_step_scale(net: &RoadNetwork, pos: &mut LanePos, sidewalks: bool) -> f64 {
    use crate::dynamics::ESMINI_SMALL_NUMBER as SMALL_NUMBER;
    let Some(road) = net.roads.get(pos.road) else { return 1.0 };
    let s = pos.s.clamp(0.0, road.length);
    let curvature = super::pose_memo::reference_pose(road, s).curvature;
    if curvature.abs() <= SMALL_NUMBER {
        return 1.0;
    }
    let t = lane_t(road, s, pos);
    if curvature * t <= 1.0 - SMALL_NUMBER {
        return 1.0 / (1.0 - curvature * t);
    }
    relocate(net, pos, sidewalks);
    let Some(road) = net.roads.get(pos.road) else { return 1.0 };
    let s = pos.s.clamp(0.0, road.length);
    let curvature = super::pose_memo::reference_pose(road, s).curvature;
    1.0 / (1.0 - curvature * lane_t(road, s, pos))
}

/// The position's t: its lane's centre plus its offset.
fn lane_t(road: &opendrive::Road, s: f64, pos: &LanePos) -> f64 {
    super::pose_memo::lane_borders_at(road, pos.lane_id, s).map_or(0.0, |b| b.center) + pos.offset
}

/// Position::DistanceToDS's XYZ2TrackPos of the position's own world point.
fn relocate(net: &RoadNetwork, pos: &mut LanePos, sidewalks: bool) {
    let Some(world) = pos.pose(net) else { return };
    let Some(found) = super::locate::world_to_lane_on_segment(net, world.x, world.y, world.z, (pos.road, pos.s, pos.lane_id)) else { return };
    // attached to the nearest lane of the types it snaps to (LaneSection::GetClosestLaneIdx)
    let (lane_id, offset) = super::lane_snap::snap_located(net, &found, sidewalks);
    pos.road = found.road;
    pos.lane_id = lane_id;
    pos.s = found.s;
    pos.offset = offset;
}

/// The lane continuing `here` across its `end` onto the road the route takes next, if the
/// route passes this road in this direction and a lane leads there. Into a junction, esmini's
/// rule instead (`junction_arm_on_route`).
fn routed_continuation(net: &RoadNetwork, route: &routing::Route, here: LaneRef, end: ContactPoint) -> Option<(LaneRef, ContactPoint)> {
    if let Some(j) = junction_at(net, here, end) {
        return junction_arm_on_route(net, route, j, here, end);
    }
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

/// The junction arm an entity with a route takes, as esmini's Position::MoveToConnectingRoad
/// does with a valid route (Route::GetRoadAtOtherEndOfIncomingRoad): the road beyond the
/// junction is the far end of the first route road that is a connecting road of this junction
/// linked to the entity's road — whichever way the route runs, so a car reversing along its
/// route goes back the way the route came; the arm is the last connection of the entity's lane
/// leading there (one on the route first). When the route does not cross this junction from
/// this road, esmini takes the lane's first connection, not the straightest.
fn junction_arm_on_route(
    net: &RoadNetwork,
    route: &routing::Route,
    junction: &opendrive::Junction,
    here: LaneRef,
    end: ContactPoint,
) -> Option<(LaneRef, ContactPoint)> {
    let cands = junction_arms(net, here, junction, net.lanes_across(here, end));
    // esmini's connections include the counter connections it adds (`junction_connections`).
    let ji = net.junction_index(&junction.id)?;
    let entering = super::junction_connections::entering(net, ji, here.road);
    let target = route.legs().iter().find_map(|leg| {
        let r = net.roads.get(leg.road)?;
        let entered_here = entering.iter().any(|c| c.connecting == leg.road);
        (r.junction.as_deref() == Some(junction.id.as_str()) && entered_here).then(|| far_end(net, leg.road, here.road)).flatten()
    });
    let leads_to_target = |c: &&LaneRef| target.is_some() && far_end(net, c.road, here.road) == target;
    let on_route = |c: &&LaneRef| route.legs().iter().any(|l| l.road == c.road);
    let pick = cands.iter().filter(leads_to_target).find(on_route).or_else(|| cands.iter().rfind(leads_to_target)).or(cands.first())?;
    // MoveToConnectingRoad enters at the contact point the connection names (a counter
    // connection's is the flip of its original's, whatever the geometry), as without a route.
    let contact = entering
        .iter()
        .find(|c| c.connecting == pick.road && c.lane_links.iter().any(|&(from, _)| from == here.lane))
        .or_else(|| entering.iter().find(|c| c.connecting == pick.road))
        .map(|c| c.contact)
        .or_else(|| net.roads_at(here.road, end).into_iter().find(|e| e.road == pick.road).map(|e| e.contact))
        .unwrap_or(ContactPoint::Start);
    Some((*pick, contact))
}

/// The road at the other end of connecting road `road` from `incoming` (its successor when
/// that is another road, else its predecessor; esmini's order).
fn far_end(net: &RoadNetwork, road: usize, incoming: usize) -> Option<usize> {
    let r = net.roads.get(road)?;
    let incoming_id = net.roads.get(incoming).map(|x| x.id.as_str());
    [r.successor.as_ref(), r.predecessor.as_ref()]
        .into_iter()
        .flatten()
        .find(|l| l.element_type == ElementType::Road && Some(l.element_id.as_str()) != incoming_id)
        .and_then(|l| net.road_index(&l.element_id))
}

/// The lane continuing `here` across its `end`, and the contact point on that lane's road.
/// `heading_in`: the road heading the entity drives in where it is.
fn choose_continuation(net: &RoadNetwork, here: LaneRef, end: ContactPoint, heading_in: f64, arms: &mut Arms) -> Option<(LaneRef, ContactPoint)> {
    let junction = junction_at(net, here, end);
    let cands: Vec<(LaneRef, ContactPoint)> = match junction {
        // A default junction: esmini's connections from this road and lane, each entering its
        // connecting road at the contact point it names (MoveToConnectingRoad trusts it, even
        // where the connecting road's own link does not lead back here).
        Some(j) if j.kind != opendrive::JunctionType::Direct => default_junction_arms(net, here, j),
        _ => {
            let mut lanes = net.lanes_across(here, end);
            if let Some(j) = junction {
                lanes = junction_arms(net, here, j, lanes);
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
            // Only lanes leading away in the same travel sense (lanes_across gives lane links,
            // which are directional already).
            let contact_at = |c: &LaneRef| -> ContactPoint {
                if c.road != here.road {
                    contact_of(c.road)
                } else if end == ContactPoint::End {
                    ContactPoint::Start
                } else {
                    ContactPoint::End
                }
            };
            lanes.into_iter().map(|c| (c, contact_at(&c))).collect()
        }
    };
    if cands.is_empty() {
        return None;
    }
    let mut random = match arms {
        Arms::Drawn(g) if junction.is_some() => {
            let n = i32::try_from(cands.len()).unwrap_or(i32::MAX);
            let k = if n > 1 { usize::try_from(g.number_between(0, n - 1)).unwrap_or(0) } else { 0 };
            return cands.get(k).copied();
        }
        Arms::Drawn(_) => None,
        Arms::Straightest(g) => g.as_deref_mut(),
    };
    let mut best: Option<(f64, LaneRef, ContactPoint)> = None;
    for (c, contact) in cands {
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

/// A road linked to the next road whose lane `here` has no lane link there: esmini's
/// Position::MoveToConnectingRoad ("No connection … trying move to closest lane") puts the
/// entity on the next road's lane of its snap types (`sidewalks`: a pedestrian's) nearest
/// the t it had (SetTrackPos at the contact point, t as it is), at that lane's centre.
fn unlinked_lane_continuation(
    net: &RoadNetwork,
    road: &opendrive::Road,
    here: LaneRef,
    end: ContactPoint,
    pos: &LanePos,
    sidewalks: bool,
) -> Option<(LaneRef, ContactPoint)> {
    let link = road.link_at(end).filter(|l| l.element_type == ElementType::Road)?;
    // the centre lane (which esmini's stale lane index can name) has no links
    if here.lane != 0 {
        let sec = road.lane_sections.get(here.section)?;
        let lane = sec.left.iter().chain(&sec.right).find(|l| l.id == here.lane)?;
        let linked = match end {
            ContactPoint::Start => &lane.predecessors,
            ContactPoint::End => &lane.successors,
        };
        if !linked.is_empty() {
            return None;
        }
    }
    let next = net.road_index(&link.element_id)?;
    let next_road = net.roads.get(next)?;
    let contact = link.contact_point.unwrap_or(ContactPoint::Start);
    let s_contact = if contact == ContactPoint::Start { 0.0 } else { next_road.length };
    let t = pos.pose(net)?.t;
    let section = opendrive::section_at_end(next_road, contact);
    let (lane_id, _) = super::lane_snap::snap(next_road, section, s_contact, t, sidewalks)?;
    Some((LaneRef { road: next, section, lane: lane_id }, contact))
}

/// The arms of default junction `junction` lane `here` can take, in esmini's order
/// (Junction::GetRoadConnectionByIdx over `junction_connections::entering`: the file's
/// connections from this road, then its counter connections, lane links in order), each with
/// the contact point its connection names; only lanes that exist.
fn default_junction_arms(net: &RoadNetwork, here: LaneRef, junction: &opendrive::Junction) -> Vec<(LaneRef, ContactPoint)> {
    let Some(ji) = net.junction_index(&junction.id) else { return Vec::new() };
    let mut out = Vec::new();
    for conn in super::junction_connections::entering(net, ji, here.road) {
        let Some(r) = net.roads.get(conn.connecting) else { continue };
        let section = opendrive::section_at_end(r, conn.contact);
        for &(_, to) in conn.lane_links.iter().filter(|l| l.0 == here.lane) {
            // A lane link to a lane the connecting road lacks is still an arm (esmini's
            // Junction::GetRoadConnectionByIdx only logs "target lane not found"): entering it,
            // Position::SetLanePos fails after SetLongitudinalTrackPos switched the road, which
            // reset the lane id to 0, and keeps the offset; the entity goes on in lane 0.
            let exists = r.lane_sections.get(section).is_some_and(|sec| sec.left.iter().chain(&sec.right).any(|l| l.id == to));
            out.push((LaneRef { road: conn.connecting, section, lane: if exists { to } else { 0 } }, conn.contact));
        }
    }
    out
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

/// The arms of `junction` lane `here` can take, in the order esmini visits them: esmini's
/// connections from this road (the file's in document order, then its counter connections,
/// `junction_connections`), lane links in order. In a default junction a lane none of them
/// starts from cannot enter (esmini's MoveToConnectingRoad finds no connection: the entity
/// stays at the road's end); a direct junction keeps every linked lane, unnamed arms last.
fn junction_arms(net: &RoadNetwork, here: LaneRef, junction: &opendrive::Junction, mut cands: Vec<LaneRef>) -> Vec<LaneRef> {
    let Some(ji) = net.junction_index(&junction.id) else { return cands };
    let conns = super::junction_connections::entering(net, ji, here.road);
    let rank = |c: &LaneRef| -> usize {
        let mut k = 0usize;
        for conn in &conns {
            for &(_, to) in conn.lane_links.iter().filter(|l| l.0 == here.lane) {
                if conn.connecting == c.road && to == c.lane {
                    return k;
                }
                k += 1;
            }
        }
        usize::MAX
    };
    if junction.kind != opendrive::JunctionType::Direct {
        cands.retain(|c| rank(c) != usize::MAX);
    }
    // Stable: equal ranks (unnamed arms) keep lanes_across's road order.
    cands.sort_by_key(|c| rank(c));
    cands
}

/// Keep the lane across a lane-section boundary inside one road, following lane links (no
/// link: the same id). Where that lane is missing or not of a type the entity snaps to
/// (`sidewalks`: a pedestrian's), esmini's Road::GetLaneInfoByS takes the lane of those types
/// nearest the old lane's centre there (LaneSection::GetClosestLaneIdx), the offset kept: a
/// car whose merge lane ends in a stop lane moves into the lane beside it.
fn follow_section_change(net: &RoadNetwork, pos: &mut LanePos, before: usize, now: usize, sidewalks: bool) {
    let Some(road) = net.roads.get(pos.road) else { return };
    let end = if now > before { ContactPoint::End } else { ContactPoint::Start };
    let old_lane = pos.lane_id;
    let next = net.lanes_across(LaneRef { road: pos.road, section: before, lane: old_lane }, end);
    if let Some(n) = next.iter().find(|n| n.road == pos.road) {
        pos.lane_id = n.lane;
    }
    if old_lane == 0 {
        return;
    }
    let allowed = |k: opendrive::LaneType| k.is_any_driving() || (sidewalks && k == opendrive::LaneType::Sidewalk);
    let usable = road.lane_sections.get(now).is_some_and(|sec| sec.left.iter().chain(&sec.right).any(|l| l.id == pos.lane_id && allowed(l.kind)));
    if usable {
        return;
    }
    // The old lane's centre at this s, its section's widths carried on past its end.
    let Some(old) = lane_borders(road, before, old_lane, pos.s) else { return };
    if let Some((lane_id, _)) = super::lane_snap::snap(road, now, pos.s, old.center, sidewalks) {
        pos.lane_id = lane_id;
    }
}

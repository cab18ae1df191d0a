//! What esmini's NaturalDriver sees around it: the road-network delta between two entities
//! (signed distance along the roads, lane difference), the free space between their bounding
//! boxes, the six vehicles of interest (closest ahead and behind in its own lane and in the
//! lanes to the left and right), the driving lanes next to it, and the IDM acceleration it
//! predicts for any follower/leader pair.

use super::state::NdParams;
use crate::angles::wrap;
use crate::entities::Entity;
use crate::roads::lane_side::lane_delta;
use crate::roads::road_distance::road_distance_within;
use crate::roads::{move_along_s, LanePos};
use crate::sim::Sim;
use opendrive::{ContactPoint, RoadNetwork};

/// esmini's SMALL_NUMBER and LARGE_NUMBER (CommonMini.hpp: 1e-6 and 1e10).
pub(crate) const SMALL_NUMBER: f64 = crate::dynamics::ESMINI_SMALL_NUMBER;
pub(crate) const LARGE_NUMBER: f64 = 1e10;

/// Slots of the vehicles of interest.
pub(crate) const LEAD: usize = 0;
pub(crate) const FOLLOWING: usize = 1;
pub(crate) const LEFT_LEAD: usize = 2;
pub(crate) const LEFT_FOLLOW: usize = 3;
pub(crate) const RIGHT_LEAD: usize = 4;
pub(crate) const RIGHT_FOLLOW: usize = 5;

/// The closest vehicle of each kind: entity index and signed distance along the road.
pub(crate) type Vois = [Option<(usize, f64)>; 6];

/// Road delta from `a` to `b` as esmini's `Position::Delta` has it: signed distance along the
/// roads (positive ahead of the way `a` faces) and lane difference (b's lane id minus a's, by
/// one less across the centre lane: whatever side of the road `a` drives on, as esmini's
/// `diff.dLaneId`). On one road the distance is the difference of s whatever its size; across
/// roads the shortest chain within `max`, searched forward and, when `both`, backward. `None`
/// when no path is found.
pub(crate) fn road_delta(net: &RoadNetwork, a: &LanePos, b: &LanePos, both: bool, max: f64) -> Option<(f64, i32)> {
    // Position::Delta: found only when RoadPath::Calculate succeeds and |dist| < maxDist.
    road_delta_any(net, a, b, both, max).filter(|(d, _)| d.abs() < max)
}

fn road_delta_any(net: &RoadNetwork, a: &LanePos, b: &LanePos, both: bool, max: f64) -> Option<(f64, i32)> {
    if a.road == b.road {
        return Some(((b.s - a.s) * a.dir, lane_delta(a.lane_id, b.lane_id)));
    }
    let d = road_distance_within(net, a.road, a.s, b.road, b.s, max)?;
    let mut p = *a;
    move_along_s(net, &mut p, d);
    if p.road == b.road {
        return Some((d, lane_delta(p.lane_id, b.lane_id)));
    }
    if both {
        let mut p = *a;
        move_along_s(net, &mut p, -d);
        if p.road == b.road {
            return Some((-d, lane_delta(p.lane_id, b.lane_id)));
        }
    }
    // `a`'s lane leads elsewhere, but b's road is linked to a's own end (by a road link or a
    // junction connection): esmini's RoadPath::Calculate takes that last step whatever the lane,
    // and Position::Delta then finds no connecting lane into b's road (Road::GetConnectingLaneId
    // gives 0), so it measures b's lane from the reference lane 0.
    let linked = |end: ContactPoint| net.roads_at(a.road, end).iter().any(|e| e.road == b.road);
    let (ahead, behind) = if a.dir >= 0.0 { (ContactPoint::End, ContactPoint::Start) } else { (ContactPoint::Start, ContactPoint::End) };
    if linked(ahead) {
        return Some((d, lane_delta(0, b.lane_id)));
    }
    if both && linked(behind) {
        return Some((-d, lane_delta(0, b.lane_id)));
    }
    None
}

/// Free space between `follow` and `target` along the road given the reference-point distance
/// `ds` (esmini's EstimateFreespace): bounding-box overhangs removed when both point roughly the
/// same way, clipped at 0; the raw distance otherwise.
pub(crate) fn freespace(follow: &Entity, target: &Entity, ds: f64) -> f64 {
    if wrap(follow.h - target.h).abs() >= std::f64::consts::FRAC_PI_2 {
        return ds;
    }
    let overhang = (follow.bbox[3] / 2.0 + follow.bbox[0]) + (target.bbox[3] / 2.0 - target.bbox[0]);
    if ds > 0.0 {
        (ds - overhang).max(0.0)
    } else {
        (ds + overhang).min(0.0)
    }
}

/// IDM desired gap s0 + max(0, v·T + v·Δv / (2·√(a·b))).
pub(crate) fn desired_gap(p: &NdParams, follow_speed: f64, lead_speed: f64) -> f64 {
    let ab = -p.max_acc * p.max_dec;
    p.desired_distance + (follow_speed * p.thw + follow_speed * (follow_speed - lead_speed) / (2.0 * ab.sqrt())).max(0.0)
}

/// The driving lanes to the left and right of `lp` (0: none), or `None` when its side of the
/// road has at most one driving lane (esmini's ControllerNaturalDriver::AdjacentLanesAvailable).
/// esmini keeps a section's lanes sorted by id, + to − with the centre lane, and decides the
/// side away from the outer edge by the lane's index: on the right-hand side a lane whose index
/// is the largest minus the number of left lanes has no left neighbour (the outer lane of a road
/// with right lanes only, e.g. a junction's connecting road), on the left-hand side a lane whose
/// index + 1 is the number of right lanes; otherwise the neighbour must be a driving lane (the
/// centre lane never is).
pub(crate) fn adjacent_lanes(net: &RoadNetwork, lp: &LanePos) -> Option<[i32; 2]> {
    let road = net.roads.get(lp.road)?;
    let sec = road.lane_sections.get(road.section_index_at(lp.s.clamp(0.0, road.length)))?;
    let cur = lp.lane_id;
    if cur == 0 {
        return None;
    }
    let side = if cur > 0 { &sec.left } else { &sec.right };
    if side.iter().filter(|l| l.kind.is_any_driving()).count() <= 1 {
        return None;
    }
    let driving = |id: i32| id != 0 && id.signum() == cur.signum() && side.iter().any(|l| l.id == id && l.kind.is_any_driving());
    let centre = usize::from(sec.center.is_some());
    let max_idx = (sec.left.len() + centre + sec.right.len()).saturating_sub(1);
    let idx = sec.left.iter().filter(|l| l.id > cur).count() + if cur < 0 { centre } else { 0 } + sec.right.iter().filter(|l| l.id > cur).count();
    let (left, right) = (cur - cur.signum(), cur + cur.signum());
    let (left_ok, right_ok) = if cur < 0 {
        (idx != max_idx.saturating_sub(sec.left.len()) && driving(left), idx != max_idx && driving(right))
    } else {
        (idx + 1 != sec.right.len() && driving(left), idx != 0 && driving(right))
    };
    Some([if left_ok { left } else { 0 }, if right_ok { right } else { 0 }])
}

impl<'a> Sim<'a> {
    /// Other active entities within `radius` (straight-line distance of the reference points),
    /// as esmini's distance cache lets the driver measure them (`distance_cache.rs`).
    pub(super) fn nd_in_radius(&mut self, e: usize, radius: f64) -> Vec<usize> {
        (0..self.entities.len()).filter(|&i| i != e).filter(|&i| self.nd_cached_distance(e, i, 2.0 * radius).is_some_and(|d| d.abs() <= radius)).collect()
    }

    /// Delta from entity `a` to entity `b` with esmini's fallback when no path is found
    /// (distance LARGE_NUMBER, same lane).
    pub(super) fn nd_delta(&self, a: usize, b: usize, both: bool, max: f64) -> (f64, i32) {
        let found = match (self.net, self.entities.get(a).and_then(|x| x.lane), self.entities.get(b).and_then(|x| x.lane)) {
            (Some(net), Some(la), Some(lb)) => road_delta(net, &la, &lb, both, max),
            _ => None,
        };
        found.unwrap_or((LARGE_NUMBER, 0))
    }

    /// The vehicles of interest of entity `e` among `around` (esmini's UpdateSurroundingVehicles:
    /// the lane difference times minus the sign of its own lane, 1 left and -1 right, so a car
    /// on a positive lane files the lane further out as its right one, as esmini does).
    pub(super) fn nd_vois(&self, e: usize, around: &[usize], lookahead: f64) -> Vois {
        let mut v: Vois = [None; 6];
        let my_lane = self.entities.get(e).and_then(|x| x.lane).map_or(0, |l| l.lane_id);
        for &i in around {
            let (ds, dlane) = self.nd_delta(e, i, true, lookahead);
            let side = dlane * -my_lane.signum();
            let (ahead, behind) = match (dlane, side) {
                (0, _) => (LEAD, FOLLOWING),
                (_, 1) => (LEFT_LEAD, LEFT_FOLLOW),
                (_, -1) => (RIGHT_LEAD, RIGHT_FOLLOW),
                _ => continue,
            };
            if ds >= 0.0 {
                if v[ahead].is_none_or(|(_, d)| ds < d) {
                    v[ahead] = Some((i, ds));
                }
            } else if v[behind].is_none_or(|(_, d)| ds > d) {
                v[behind] = Some((i, ds));
            }
        }
        v
    }

    /// IDM acceleration of `follow` behind `lead` with the driver's parameters (0 without a
    /// follower; free road without a leader).
    pub(super) fn nd_idm(&self, p: &NdParams, follow: Option<usize>, lead: Option<usize>) -> f64 {
        let Some((fi, f)) = follow.and_then(|i| self.entities.get(i).map(|x| (i, x))) else { return 0.0 };
        let v = f.speed;
        let mut acc = p.max_acc * (1.0 - (v / p.desired_speed).powi(4));
        if let Some((li, l)) = lead.and_then(|i| self.entities.get(i).map(|x| (i, x))) {
            let gap = desired_gap(p, v, l.speed);
            let (ds, _) = self.nd_delta(fi, li, false, p.lookahead);
            let mut free = freespace(f, l, ds);
            if free == 0.0 {
                free = SMALL_NUMBER;
            }
            acc -= p.max_acc * (gap / free).powi(2);
        }
        acc
    }
}

//! RelativeClearanceCondition as esmini evaluates it: true when no other entity (or none of the
//! listed ones) is inside the window [-distanceBackward, distanceForward] along the road in the
//! relative lane range, *and* the range names at least one existing driving lane at the
//! entity's position (a free but non-existent lane is not clearance).

use super::free_space::{free_space_road, free_space_roads, FreeSpaceGap};
use crate::entities::Entity;
use crate::roads::road_distance::road_distance_within;
use crate::sim::Sim;
use opendrive::{Road, RoadNetwork};

/// The parameters of one RelativeClearanceCondition.
pub(crate) struct Clearance<'c> {
    pub entities: &'c [String],
    pub opposite_lanes: bool,
    pub free_space: bool,
    pub forward: f64,
    pub backward: f64,
    /// Relative lane range (from, to); open ends are unbounded.
    pub from: i64,
    pub to: i64,
}

impl<'c> Clearance<'c> {
    /// The parameters of `cond` when it is a RelativeClearanceCondition (esmini's defaults: no
    /// distance, an unbounded lane range; only the first RelativeLaneRange counts).
    pub(crate) fn of(cond: &'c openscenario::EntityCondition) -> Option<Self> {
        let openscenario::EntityCondition::RelativeClearance { entities, opposite_lanes, free_space, distance_forward, distance_backward, lane_ranges } = cond
        else {
            return None;
        };
        let (from, to) = lane_ranges.first().copied().unwrap_or((None, None));
        Some(Clearance {
            entities,
            opposite_lanes: *opposite_lanes,
            free_space: *free_space,
            forward: distance_forward.unwrap_or(0.0),
            backward: distance_backward.unwrap_or(0.0),
            from: from.map_or(i64::MIN / 4, i64::from),
            to: to.map_or(i64::MAX / 4, i64::from),
        })
    }
}

impl<'a> Sim<'a> {
    /// Whether entity `idx` has the clearance `c` around it. `found` is esmini's objFound in
    /// TrigByRelativeClearance::CheckCondition: set by each entity it compares, and kept from
    /// the previous triggering entity when none is compared (the only listed entity is the
    /// triggering one itself), so that entity then has clearance only if the previous one had.
    pub(super) fn relative_clearance(&self, idx: usize, c: &Clearance, found: &mut bool) -> bool {
        let (Some(net), Some(me)) = (self.net, self.entities.get(idx)) else { return false };
        let Some(lp) = me.lane else { return false };
        let Some(road) = net.roads.get(lp.road) else { return false };
        let others: Vec<usize> =
            if c.entities.is_empty() { (0..self.entities.len()).collect() } else { c.entities.iter().filter_map(|n| self.entity_index(n)).collect() };
        for o in others.into_iter().filter(|&j| j != idx).filter_map(|j| self.entities.get(j)) {
            if !o.active {
                continue;
            }
            *found = delta(net, me, o, c.forward.max(c.backward), c.free_space).is_some_and(|(ds, dlane, opposite)| {
                ds >= -c.backward && ds <= c.forward && dlane >= c.from && dlane <= c.to && (c.opposite_lanes || !opposite)
            });
            if *found {
                break;
            }
        }
        !*found && lane_exists(road, lp.s, lp.lane_id as i64, c)
    }
}

/// Some driving lane at `s` with an id in `own + from ..= own + to` (same side unless opposite
/// lanes are allowed). Lane ids are offset arithmetically, as esmini does.
fn lane_exists(road: &Road, s: f64, own: i64, c: &Clearance) -> bool {
    let Some(sec) = road.lane_sections.get(road.section_index_at(s)) else { return false };
    let (lo, hi) = (own.saturating_add(c.from), own.saturating_add(c.to));
    sec.left.iter().chain(sec.right.iter()).any(|l| {
        let id = l.id as i64;
        l.kind.is_any_driving() && id >= lo && id <= hi && (c.opposite_lanes || id.signum() == own.signum())
    })
}

/// Road-level difference from `a` to `b`: signed ds (+ ahead of `a`), lane difference (b − a)
/// and whether `b` is on a lane of the other direction. `None`: not within `max` along the roads.
fn delta(net: &RoadNetwork, a: &Entity, b: &Entity, max: f64, free_space: bool) -> Option<(f64, i64, bool)> {
    let (la, lb) = (a.lane?, b.lane?);
    // esmini's Object::FreeSpaceDistanceObjectRoadLane: the gap between the boxes' corners, and
    // the lane difference of the last corners compared, the front right ones (0 when the boxes
    // overlap). Corners on other roads than `a`'s are located from `a`'s position and measured
    // along the road path (`free_space_roads`: where the corners straddle a road end the
    // deltas of one corner disagree in sign and the gap is 0); where no path joins a pair the
    // function fails and the entity is not found.
    let gap = if free_space {
        let same = if la.road == lb.road { free_space_road(net, a, b, la.road, la.dir) } else { None };
        Some(same.or_else(|| free_space_roads(net, a, b, la.road))?)
    } else {
        None
    };
    // esmini's Position::Delta: the first position's lane carried along the road path onto the
    // second's road
    let carried = |(ra, sa, ia): (usize, f64, i32), (rb, sb): (usize, f64)| crate::roads::road_path::lane_carried(net, ra, sa, ia, rb, sb).unwrap_or(ia);
    let (ds, la_id, lb_id) = match gap {
        Some(FreeSpaceGap { front_right: None, .. }) => return Some((0.0, 0, false)),
        // the front right corners' Delta: the corners may lie on two roads
        Some(FreeSpaceGap { ds, front_right: Some((ca, cb)), .. }) => (ds, carried((ca.road, ca.s, ca.lane_id), (cb.road, cb.s)), cb.lane_id),
        None => {
            let ds = centre_ds(net, a, b, max, free_space)?;
            (ds, carried((la.road, la.s, la.lane_id), (lb.road, lb.s)), lb.lane_id)
        }
    };
    if ds.abs() > max + 1e-9 {
        return None;
    }
    // across the reference line the centre lane is not counted
    let mut dlane = lb_id as i64 - la_id as i64;
    // esmini's SIGN (a lane that does not continue is 0, on the positive side)
    let opposite = crate::roads::lane_side::side(la_id) != crate::roads::lane_side::side(lb_id);
    if opposite {
        dlane = (dlane.abs() - 1) * dlane.signum();
    }
    Some((ds, dlane, opposite))
}

/// Signed ds from `a`'s reference point to `b`'s along the roads (less both boxes' extents along
/// the way with `free_space`); `None`: not within `max`.
fn centre_ds(net: &RoadNetwork, a: &Entity, b: &Entity, max: f64, free_space: bool) -> Option<f64> {
    let (la, lb) = (a.lane?, b.lane?);
    let mut ds = if la.road == lb.road {
        (lb.s - la.s) * la.dir
    } else {
        let d = road_distance_within(net, la.road, la.s, lb.road, lb.s, max)?;
        // RoadPath::Calculate's sign (direction_, turned again for `a` facing against its
        // lane's driving direction), as Position::Distance's
        super::distance::signed_path_ds(net, a, b, d)?
    };
    if free_space {
        let ext = if ds >= 0.0 { 0.5 * a.bbox[3] + a.bbox[0] + 0.5 * b.bbox[3] - b.bbox[0] } else { 0.5 * a.bbox[3] - a.bbox[0] + 0.5 * b.bbox[3] + b.bbox[0] };
        ds = if ds.abs() <= ext { 0.0 } else { ds - ext * ds.signum() };
    }
    Some(ds)
}

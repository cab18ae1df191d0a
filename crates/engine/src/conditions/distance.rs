//! Distances between entities (and from an entity to a point) in the coordinate systems of
//! the standard: entity (the first entity's heading), road and lane (s and t along the road),
//! world; longitudinal, lateral or euclidean; between reference points or bounding boxes
//! (freespace). Longitudinal and lateral results are signed: positive ahead / to the left.

use super::boxes::{box_distance, corners, interval_gap};
use super::free_space::{free_space_point_road, free_space_point_roads, free_space_road, free_space_roads};
use crate::controllers::natural_driver::view::LARGE_NUMBER;
use crate::entities::Entity;
use crate::roads::lane_geometry::lane_center_t;
use opendrive::RoadNetwork;
use openscenario::{CoordinateSystem, RelativeDistanceType};

fn road_t(net: &RoadNetwork, e: &Entity) -> Option<(usize, f64, f64, f64)> {
    let lp = e.lane?;
    let road = net.roads.get(lp.road)?;
    Some((lp.road, lp.s, lane_center_t(road, lp.lane_id, lp.s)? + lp.offset, lp.dir))
}

/// Position::Distance in road coordinates between entities on different roads: the distance
/// along the linked roads (Position::Delta's ds), positive when `b` lies ahead in the direction
/// `a` faces; None when no chain of roads joins them.
fn path_ds(net: &RoadNetwork, a: &Entity, b: &Entity) -> Option<f64> {
    let (la, lb) = (a.lane?, b.lane?);
    let d = crate::roads::road_distance::road_distance(net, la.road, la.s, lb.road, lb.s)?;
    signed_path_ds(net, a, b, d)
}

/// `path_ds`'s sign for an unsigned road-path length `d` from `a` to `b` (on different roads).
pub(crate) fn signed_path_ds(net: &RoadNetwork, a: &Entity, b: &Entity, d: f64) -> Option<f64> {
    let (la, lb) = (a.lane?, b.lane?);
    // RoadPath::Calculate's direction: ahead (+) when the path leaves a's road by its end
    // and a faces along s, or by its start and a faces against s; behind (−) otherwise. A
    // trial move that far along the roads (the straightest arms) settles most pairs without
    // the path search: where it reaches b, b is ahead.
    let mut p = la;
    crate::roads::move_along_road_s(net, &mut p, d, None, None);
    let d = if p.road == lb.road && (p.s - lb.s).abs() < (0.05 * d).max(1.0) {
        d
    } else {
        match crate::roads::road_path::path_ends(net, la.road, la.s, la.lane_id, lb.road) {
            Some(pe) if (pe.first_exit == opendrive::ContactPoint::Start) != (la.dir > 0.0) => d,
            _ => -d,
        }
    };
    // RoadPath::Calculate (across roads only) turns the sign once more for a start position
    // facing against its lane's driving direction, as in SynchronizeAction's master_distance
    if let (Some(r), Some(pose)) = (net.roads.get(la.road), la.pose(net)) {
        if crate::roads::driving_direction::faces_against(r.rule, la.lane_id, pose.road_heading, crate::entities::position_heading(Some(net), a)) {
            return Some(-d);
        }
    }
    Some(d)
}

/// Distance from entity `a` to entity `b`.
pub(crate) fn between(net: Option<&RoadNetwork>, a: &Entity, b: &Entity, cs: CoordinateSystem, kind: RelativeDistanceType, freespace: bool) -> f64 {
    // esmini's Position::Distance and Object::Distance measure a euclidean distance in the
    // world (getRelativeDistance: negative when `b` is not ahead; FreeSpaceDistance for boxes)
    // whatever the coordinate system; only longitudinal and lateral ones go along the road.
    if matches!(cs, CoordinateSystem::Road | CoordinateSystem::Lane) && kind != RelativeDistanceType::EuclidianDistance {
        if let (Some(net), Some(ra), Some(rb)) = (net, net.and_then(|n| road_t(n, a)), net.and_then(|n| road_t(n, b))) {
            let _ = net;
            // esmini's Object::Distance with freeSpace in road coordinates:
            // FreeSpaceDistanceObjectRoadLane, corner by corner (dt as t grows, whichever way
            // `a` faces), each corner located from `a`'s position and a pair on different roads
            // measured along the road path between them; where no path joins a pair it fails
            // and the conditions read LARGE_NUMBER. A point (to_point: no box) is
            // FreeSpaceDistancePointRoadLane's, not this.
            if freespace && b.bbox[3] > 0.0 {
                let same = if ra.0 == rb.0 { free_space_road(net, a, b, ra.0, ra.3) } else { None };
                let gap = same.or_else(|| free_space_roads(net, a, b, ra.0));
                return match gap {
                    Some(g) if kind == RelativeDistanceType::Longitudinal => g.ds,
                    Some(g) => g.dt,
                    None => LARGE_NUMBER,
                };
            }
            if ra.0 == rb.0 {
                // Position::Delta on one road: ds along the way `a` faces (RoadPath::Calculate),
                // dt = tB − tA whichever way (a target right of the reference line is negative)
                let ds = (rb.1 - ra.1) * ra.3;
                let dt = rb.2 - ra.2;
                // (a euclidean distance does not come here)
                return if kind == RelativeDistanceType::Longitudinal {
                    if freespace {
                        shrink(ds, a.bbox[3] * 0.5 + a.bbox[0] * ds.signum(), b.bbox[3] * 0.5 - b.bbox[0] * ds.signum())
                    } else {
                        ds
                    }
                } else if freespace {
                    shrink(dt, a.bbox[4] * 0.5, b.bbox[4] * 0.5)
                } else {
                    dt
                };
            }
            // Where no road path joins the roads, esmini's Position::Delta leaves ds and dt at
            // LARGE_NUMBER and Position::Distance fails: the conditions read LARGE_NUMBER
            // (TrigByRelativeDistance, TrigByTimeHeadway, …), LongDistanceAction::Step the ds.
            if kind == RelativeDistanceType::Longitudinal && !freespace {
                return path_ds(net, a, b).unwrap_or(LARGE_NUMBER);
            }
            // Position::Delta's dt across roads: b's t less a's, or plus it where the path
            // turns the lane ids around (a's lane mapped onto b's road changes sign)
            if kind == RelativeDistanceType::Lateral && !freespace {
                let flips =
                    a.lane.and_then(|la| Some(crate::roads::road_path::path_ends(net, ra.0, ra.1, la.lane_id, rb.0)?.dt_flips(net, rb.0, rb.1, la.lane_id)));
                return match flips {
                    Some(true) => rb.2 + ra.2,
                    Some(false) => rb.2 - ra.2,
                    None => LARGE_NUMBER,
                };
            }
        }
    }
    let (ux, uy) = (a.h.cos(), a.h.sin());
    // Between reference points esmini signs the euclidean distance by the longitudinal part in
    // a's frame: negative when b is not strictly ahead.
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let (lon, lat) = (dx * ux + dy * uy, -dx * uy + dy * ux);
    match kind {
        RelativeDistanceType::Longitudinal => {
            if freespace {
                interval_gap(&corners(a), &corners(b), ux, uy)
            } else {
                lon
            }
        }
        RelativeDistanceType::Lateral => {
            if freespace {
                interval_gap(&corners(a), &corners(b), -uy, ux)
            } else {
                lat
            }
        }
        RelativeDistanceType::EuclidianDistance => {
            if freespace {
                signed_box_distance(a, b)
            } else {
                let d = lon.hypot(lat);
                if lon > 0.0 {
                    d
                } else {
                    -d
                }
            }
        }
    }
}

/// What esmini's Object::FreeSpaceDistance gives for boxes `a` and `b`: the free distance,
/// and the lateral and longitudinal gaps in `a`'s frame.
fn box_gaps(a: &Entity, b: &Entity) -> (f64, f64, f64) {
    let (ca, cb) = (corners(a), corners(b));
    let (ux, uy) = (a.h.cos(), a.h.sin());
    (box_distance(&ca, &cb), interval_gap(&ca, &cb, -uy, ux), interval_gap(&ca, &cb, ux, uy))
}

/// A freespace distance between towing chains, as esmini's Object::Distance measures it with
/// freeSpace: `pivots` is the measuring entity's chain from its front-most tow vehicle back,
/// `targets` the other's (or the point, as `to_point` makes it). Euclidean or in the entity
/// frame: of the pairs of boxes, the one nearest each other (the first on a tie, stopping at a
/// touch), its free distance signed by its longitudinal gap in the pivot's frame, or that pair's
/// lateral / longitudinal gap. In road or lane coordinates each pivot is measured to the first
/// target alone (FreeSpaceDistanceObjectRoadLane is handed the target, never its trailers):
/// the smallest gap.
pub(crate) fn between_chains(net: Option<&RoadNetwork>, pivots: &[&Entity], targets: &[&Entity], cs: CoordinateSystem, kind: RelativeDistanceType) -> f64 {
    let (Some(&a), Some(&b)) = (pivots.first(), targets.first()) else { return LARGE_NUMBER };
    if pivots.len() == 1 && targets.len() == 1 {
        return between(net, a, b, cs, kind, true);
    }
    if matches!(cs, CoordinateSystem::Road | CoordinateSystem::Lane) && kind != RelativeDistanceType::EuclidianDistance {
        let mut best = LARGE_NUMBER;
        for &p in pivots {
            let d = between(net, p, b, cs, kind, true);
            if d.abs() < best.abs() {
                best = d;
            }
            if best == 0.0 {
                break;
            }
        }
        return best;
    }
    let mut best: Option<(f64, f64, f64)> = None;
    'pivots: for &p in pivots {
        for &t in targets {
            let g = box_gaps(p, t);
            if best.is_none_or(|b| g.0.abs() < b.0.abs()) {
                best = Some(g);
            }
            if best.is_some_and(|b| b.0 == 0.0) {
                break 'pivots;
            }
        }
    }
    let Some((d, lat, lon)) = best else { return LARGE_NUMBER };
    match (cs, kind) {
        (CoordinateSystem::Entity, RelativeDistanceType::Lateral) => lat,
        (CoordinateSystem::Entity, RelativeDistanceType::Longitudinal) => lon,
        _ if lon < -crate::dynamics::ESMINI_SMALL_NUMBER => -d,
        _ => d,
    }
}

/// The point (x, y) as `a` measures to it: an entity without a box there.
fn point_entity(a: &Entity, x: f64, y: f64) -> Entity {
    let mut p = a.clone();
    p.x = x;
    p.y = y;
    p.bbox = [0.0; 6];
    p
}

/// A freespace distance from a towing chain (`pivots`, as for `between_chains`) to the point
/// (x, y): esmini's Object::Distance(x, y) measures from each vehicle of the chain.
pub(crate) fn chain_to_point(net: Option<&RoadNetwork>, pivots: &[&Entity], x: f64, y: f64, cs: CoordinateSystem, kind: RelativeDistanceType) -> f64 {
    let Some(&a) = pivots.first() else { return LARGE_NUMBER };
    if pivots.len() == 1 {
        return to_point(net, a, x, y, cs, kind, true);
    }
    if matches!(cs, CoordinateSystem::Road | CoordinateSystem::Lane) && kind != RelativeDistanceType::EuclidianDistance {
        let mut best = LARGE_NUMBER;
        for &p in pivots {
            let d = to_point(net, p, x, y, cs, kind, true);
            if d.abs() < best.abs() {
                best = d;
            }
            if best == 0.0 {
                break;
            }
        }
        return best;
    }
    between_chains(net, pivots, &[&point_entity(a, x, y)], cs, kind)
}

/// The free space between the boxes of `a` and `b`, negative when `b`'s box lies wholly behind
/// `a`'s along `a`'s heading: esmini's Object::Distance with freeSpace and a euclidean distance
/// (any coordinate system) signs Object::FreeSpaceDistance by the longitudinal gap
/// CollisionAndRelativeDistLatLong measures on the pivot's axis (0, so positive, when the boxes
/// overlap along it). TimeHeadway then ignores a target behind, and TimeToCollision sees one
/// closing in from behind.
fn signed_box_distance(a: &Entity, b: &Entity) -> f64 {
    let (ca, cb) = (corners(a), corners(b));
    let d = box_distance(&ca, &cb);
    if interval_gap(&ca, &cb, a.h.cos(), a.h.sin()) < -crate::dynamics::ESMINI_SMALL_NUMBER {
        -d
    } else {
        d
    }
}

/// A signed distance reduced by extents on both sides, not past zero.
fn shrink(d: f64, ext_a: f64, ext_b: f64) -> f64 {
    let m = d.abs() - ext_a.max(0.0) - ext_b.max(0.0);
    if m <= 0.0 {
        0.0
    } else {
        m * d.signum()
    }
}

/// Distance from entity `a` to the point (x, y), a point that may move (relative to an entity).
pub(crate) fn to_point(net: Option<&RoadNetwork>, a: &Entity, x: f64, y: f64, cs: CoordinateSystem, kind: RelativeDistanceType, freespace: bool) -> f64 {
    to_point_with_hint(net, a, x, y, cs, kind, freespace, true)
}

/// [`to_point`]; `moving` false for a fixed point, which in road coordinates is placed as
/// esmini places it, by a search of all roads (its result memoised), never from the entity's
/// road: from a road with no path to the point's, the distance is LARGE_NUMBER.
#[allow(clippy::too_many_arguments)]
pub(crate) fn to_point_with_hint(
    net: Option<&RoadNetwork>,
    a: &Entity,
    x: f64,
    y: f64,
    cs: CoordinateSystem,
    kind: RelativeDistanceType,
    freespace: bool,
    moving: bool,
) -> f64 {
    let mut p = point_entity(a, x, y);
    if matches!(cs, CoordinateSystem::Road | CoordinateSystem::Lane) {
        if let Some(n) = net {
            // A moving point: the entity's road first, then a search of all roads. esmini's
            // Position::Distance maps the point by a fresh Position (a search of all roads;
            // only Object::FreeSpaceDistancePointRoadLane starts from the entity's road), but
            // that search on every step of a moving target cost 6 % of the engine's time on the
            // corpus (the speed bench); the two differ only where roads overlap. A fixed point
            // is searched for once and remembered.
            let hint = if moving || freespace { a.lane.map(|l| (l.road, l.s)) } else { None };
            // Where the point is off the entity's road: with freespace
            // (FreeSpaceDistancePointRoadLane) it is mapped from the entity's position, without
            // it (Position::Distance) by a fresh Position, which on roads lying equally near
            // keeps the first (the connecting roads through a junction's centre)
            let located =
                if freespace { crate::roads::locate::world_to_lane_memo(n, x, y, hint) } else { crate::roads::locate::world_to_lane_fresh(n, x, y, hint) };
            if let Some(lp) = located {
                p.lane = Some(crate::roads::LanePos { road: lp.road, lane_id: lp.lane_id, s: lp.s, offset: lp.offset, dir: 1.0 });
                // a box to a point: its corners, not its extents (FreeSpaceDistancePointRoadLane),
                // each corner's Position::Delta to the point, along the road path where they
                // lie on different roads; not measured (Object::Distance fails: the conditions
                // read LARGE_NUMBER) where no path joins them
                if freespace && kind != RelativeDistanceType::EuclidianDistance {
                    if let Some(la) = a.lane {
                        let gap = if la.road == lp.road { free_space_point_road(n, a, lp.s, lp.t, lp.road, la.dir) } else { None };
                        let (ds, dt) = gap.or_else(|| free_space_point_roads(n, a, &lp, la.road)).unwrap_or((LARGE_NUMBER, LARGE_NUMBER));
                        return if kind == RelativeDistanceType::Longitudinal { ds } else { dt };
                    }
                }
            }
        }
    }
    between(net, a, &p, cs, kind, freespace)
}

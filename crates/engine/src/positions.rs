//! Resolving an OpenSCENARIO position to a world pose and, where it names one, a lane position.
//!
//! Headings as esmini places entities: a lane or road position without orientation faces the
//! lane's driving direction; a relative orientation turns from there (a RoadPosition's from the
//! road's reference direction, on either side); an absolute one is the world heading. Relative object/world positions take the reference entity's heading.

use crate::entities::Entity;
use crate::roads::lane_geometry::{lane_borders, lane_center_t};
use crate::roads::lane_position::LanePos;
use crate::roads::road_follow::wrap;
use opendrive::{drives_along_s, RoadNetwork};
use openscenario::{Orientation, Position, ReferenceContext};
use std::f64::consts::PI;

/// Where a position puts an entity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Placement {
    pub x: f64,
    pub y: f64,
    pub z: Option<f64>,
    pub h: f64,
    /// The exact lane position when the position was given in road terms.
    pub lane: Option<LanePos>,
}

/// Why a position could not be resolved.
pub(crate) type PositionError = String;

/// Resolve `pos`; `entities` gives the reference entities of relative positions.
pub(crate) fn resolve(pos: &Position, net: Option<&RoadNetwork>, entities: &[Entity]) -> Result<Placement, PositionError> {
    let find = |name: &str| entities.iter().find(|e| e.name == name).ok_or_else(|| format!("unknown entity `{name}`"));
    match pos {
        Position::World { x, y, z, h, .. } => {
            let h = h.unwrap_or(0.0);
            // A world position is given in the OpenDRIVE file's own frame: the header offset
            // moves it with the roads (esmini's ScenarioReader::parseOSCPosition).
            match net.and_then(|n| n.header.offset) {
                Some(o) => {
                    let (x, y, _) = o.apply(*x, *y, 0.0);
                    let h = (h + o.hdg).rem_euclid(std::f64::consts::TAU);
                    Ok(Placement { x, y, z: z.map(|z| z + o.z), h, lane: None })
                }
                None => Ok(Placement { x: *x, y: *y, z: *z, h, lane: None }),
            }
        }
        Position::RelativeWorld { entity, dx, dy, dz, orientation } => {
            let e = find(entity)?;
            let h = orient(e.h, orientation.as_ref());
            Ok(Placement { x: e.x + dx, y: e.y + dy, z: dz.map(|d| e.z + d), h, lane: None })
        }
        Position::RelativeObject { entity, dx, dy, dz, orientation } => {
            let e = find(entity)?;
            let (s, c) = e.h.sin_cos();
            let h = orient(e.h, orientation.as_ref());
            Ok(Placement { x: e.x + dx * c - dy * s, y: e.y + dx * s + dy * c, z: dz.map(|d| e.z + d), h, lane: None })
        }
        Position::Lane { road_id, lane_id, s, offset, orientation } => {
            let net = net.ok_or("a LanePosition needs a road network")?;
            let road = net.road_index(road_id).ok_or_else(|| format!("unknown road `{road_id}`"))?;
            lane_placement(net, road, *lane_id, *s, *offset, orientation.as_ref())
        }
        Position::Road { road_id, s, t, orientation } => {
            let net = net.ok_or("a RoadPosition needs a road network")?;
            let road = net.road_index(road_id).ok_or_else(|| format!("unknown road `{road_id}`"))?;
            let mut p = road_placement(net, road, *s, *t, orientation.as_ref())?;
            // esmini turns a RoadPosition's relative heading from the road's reference
            // direction on either side of the road (a LanePosition's from the lane's direction).
            if let Some(Orientation { reference, h: Some(h), .. }) = orientation {
                if *reference != Some(ReferenceContext::Absolute) {
                    turn_from_road_direction(net, &mut p, *h);
                }
            }
            Ok(p)
        }
        Position::RelativeRoad { entity, ds, dt, orientation } => {
            let net = net.ok_or("a RelativeRoadPosition needs a road network")?;
            let e = find(entity)?;
            let lp = e.lane.ok_or_else(|| format!("entity `{entity}` is not on a road"))?;
            let road = net.roads.get(lp.road).ok_or("reference road missing")?;
            let t = lane_center_t(road, lp.lane_id, lp.s).unwrap_or(0.0) + lp.offset;
            let mut p = road_placement(net, lp.road, lp.s + ds, t + dt, orientation.as_ref())?;
            // esmini (Position::SetRelativePosition, RELATIVE_ROAD): the heading is relative to
            // the road's reference direction — along +s without an orientation — whichever
            // side of the road the entity lands on; only an absolute orientation is kept as is.
            if !matches!(orientation, Some(Orientation { reference: Some(ReferenceContext::Absolute), h: Some(_), .. })) {
                turn_from_road_direction(net, &mut p, orientation.and_then(|o| o.h).unwrap_or(0.0));
            }
            Ok(p)
        }
        Position::RelativeLane { entity, d_lane, ds, ds_lane, offset, orientation } => {
            let net = net.ok_or("a RelativeLanePosition needs a road network")?;
            let e = find(entity)?;
            let lp = e.lane.ok_or_else(|| format!("entity `{entity}` is not on a road"))?;
            let road = net.roads.get(lp.road).ok_or("reference road missing")?;
            // esmini's Position::SetRelativePosition (RELATIVE_LANE). `ds` moves along the road's
            // s axis and counts dLane and the offset as the lane ids and t do; `dsLane` moves
            // along the reference lane's driving direction and counts dLane and the offset to the
            // left of it — unless the reference entity faces along its lane's driving direction
            // on the rule's side of the road (right-hand traffic: a right lane, facing +s),
            // when they count as with `ds`.
            let along_lane = ds_lane.is_some() && ds.is_none();
            let (lane_id, offset, s) = if along_lane {
                let lane_dir = if drives_along_s(road.rule, lp.lane_id) { 1.0 } else { -1.0 };
                let forward = lp.dir > 0.0;
                let as_road = match road.rule {
                    opendrive::TrafficRule::RightHand => forward && lp.lane_id < 0,
                    opendrive::TrafficRule::LeftHand => !forward && lp.lane_id > 0,
                };
                let sign = if as_road { 1 } else { -1 };
                (step_lane(lp.lane_id, sign * d_lane), offset * f64::from(sign), lp.s + ds_lane.unwrap_or(0.0) * lane_dir)
            } else {
                (step_lane(lp.lane_id, *d_lane), *offset, lp.s + ds.unwrap_or(0.0))
            };
            let s = s.clamp(0.0, road.length);
            // Without an absolute heading the entity faces from the road's s direction, turned by
            // π with `dsLane` where the new lane drives against s (esmini's SetHeadingRelative).
            let r = road;
            if lane_borders(r, r.section_index_at(s), lane_id, s).is_none() {
                // No such lane: esmini's Position::SetRelativePosition keeps the location it moved
                // the reference to (its lane and lane offset at the new s), as SetLanePos fails.
                let along = !along_lane || drives_along_s(r.rule, lp.lane_id);
                return place(net, lp.road, lp.lane_id, s, lp.offset, along, Some(&relative_heading(orientation.as_ref())));
            }
            let along = !along_lane || drives_along_s(r.rule, lane_id);
            place(net, lp.road, lane_id, s, offset, along, Some(&relative_heading(orientation.as_ref())))
        }
        Position::Route { route, orientation, in_route } => crate::route_position::route_placement(route, in_route, orientation.as_ref(), net, entities),
        Position::Geo { .. } => Err("GeoPosition is not supported".into()),
        Position::Trajectory { trajectory, s, t, orientation } => {
            crate::trajectory_position::trajectory_placement(trajectory, *s, *t, orientation.as_ref(), net, entities)
        }
    }
}

/// A relative position's orientation as esmini reads it: none is a relative heading of 0
/// (ScenarioReader: "if no orientation specified, assume Relative is preferred").
fn relative_heading(o: Option<&Orientation>) -> Orientation {
    match o {
        Some(o) if o.h.is_some() => *o,
        Some(o) => Orientation { h: Some(0.0), ..*o },
        None => Orientation { h: Some(0.0), reference: Some(ReferenceContext::Relative), ..Default::default() },
    }
}

/// Lane id `k` lanes from `lane` (positive: towards higher ids), skipping the centre lane 0.
pub(crate) fn step_lane(lane: i32, k: i32) -> i32 {
    let mut id = lane.saturating_add(k);
    if lane != 0 && (id == 0 || id.signum() != lane.signum()) {
        id += if k > 0 { 1 } else { -1 };
    }
    id
}

fn orient(base: f64, o: Option<&Orientation>) -> f64 {
    match o {
        Some(o) => match (o.reference, o.h) {
            (Some(ReferenceContext::Absolute), Some(h)) => h,
            (_, Some(h)) => base + h,
            _ => base,
        },
        None => base,
    }
}

/// Placement on lane `lane_id` of road `road` at `s` with `offset`.
pub(crate) fn lane_placement(net: &RoadNetwork, road: usize, lane_id: i32, s: f64, offset: f64, o: Option<&Orientation>) -> Result<Placement, PositionError> {
    let r = net.roads.get(road).ok_or("road missing")?;
    let s = s.clamp(0.0, r.length);
    if lane_borders(r, r.section_index_at(s), lane_id, s).is_none() {
        return Err(format!("road `{}` has no lane {} at s = {:.3}", r.id, lane_id, s));
    }
    let along = drives_along_s(r.rule, lane_id);
    place(net, road, lane_id, s, offset, along, o)
}

fn place(net: &RoadNetwork, road: usize, lane_id: i32, s: f64, offset: f64, along: bool, o: Option<&Orientation>) -> Result<Placement, PositionError> {
    let mut lp = LanePos { road, lane_id, s, offset, dir: if along { 1.0 } else { -1.0 } };
    let pose = lp.pose(net).ok_or("lane missing")?;
    let facing = lp.facing_heading(&pose);
    let h = match o {
        Some(Orientation { reference: Some(ReferenceContext::Absolute), h: Some(h), .. }) => *h,
        // A relative heading is taken from the road's reference direction, as esmini does.
        Some(Orientation { h: Some(h), .. }) => pose.road_heading + h + if along { 0.0 } else { PI },
        _ => facing,
    };
    // Facing the other way than the lane's direction makes the entity drive against s.
    let rel = wrap(h - pose.road_heading);
    lp.dir = if rel.abs() <= std::f64::consts::FRAC_PI_2 + 1e-9 { 1.0 } else { -1.0 };
    Ok(Placement { x: pose.x, y: pose.y, z: Some(pose.z), h, lane: Some(lp) })
}

/// Face `p` at `h` from its road's reference direction; the lane direction it drives follows.
fn turn_from_road_direction(net: &RoadNetwork, p: &mut Placement, h: f64) {
    let Some(lp) = p.lane.as_mut() else { return };
    let Some(pose) = lp.pose(net) else { return };
    p.h = pose.road_heading + h;
    lp.dir = if wrap(h).abs() <= std::f64::consts::FRAC_PI_2 + 1e-9 { 1.0 } else { -1.0 };
}

/// Placement at road coordinates (s, t): the lane containing t.
pub(crate) fn road_placement(net: &RoadNetwork, road: usize, s: f64, t: f64, o: Option<&Orientation>) -> Result<Placement, PositionError> {
    let r = net.roads.get(road).ok_or("road missing")?;
    let s = s.clamp(0.0, r.length);
    let section = r.section_index_at(s);
    let mut found = None;
    if let Some(sec) = r.lane_sections.get(section) {
        for lane in sec.left.iter().chain(sec.right.iter()) {
            if let Some((a, b)) = lane_borders(r, section, lane.id, s) {
                let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
                if t >= lo && t <= hi && hi > lo {
                    found = Some((lane.id, 0.5 * (a + b)));
                    break;
                }
            }
        }
        if found.is_none() {
            // Outside the road: the outermost lane on the side of t.
            let side = if t >= r.lane_offset_at(s) { &sec.left } else { &sec.right };
            let other = if t >= r.lane_offset_at(s) { &sec.right } else { &sec.left };
            if let Some(l) = side.last().or(other.first()) {
                found = lane_center_t(r, l.id, s).map(|c| (l.id, c));
            }
        }
    }
    let (lane_id, center) = found.unwrap_or((0, r.lane_offset_at(s)));
    let along = drives_along_s(r.rule, lane_id);
    place(net, road, lane_id, s, t - center, along, o)
}

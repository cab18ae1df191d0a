//! Resolving an OpenSCENARIO position to a world pose and, where it names one, a lane position.
//!
//! Headings as esmini places entities: a lane or road position without orientation faces the
//! lane's driving direction; a relative orientation turns from there (a RoadPosition's from the
//! road's reference direction, on either side); an absolute one is the world heading. Relative object/world positions take the reference entity's heading.

use crate::angles::wrap;
use crate::entities::Entity;
use crate::roads::lane_geometry::lane_borders;
use crate::roads::lane_position::LanePos;
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
    /// The world point is not the lane position's: esmini set the road coordinates but left
    /// the world point (a RoutePosition on a lane the road does not have); moving goes on from
    /// the lane position.
    pub world_left: bool,
    /// With `world_left`: the heading relative to the road esmini's position holds (a failed
    /// RoutePosition: SetHeadingRelative after the lane was not found), which moving keeps.
    pub h_rel: Option<f64>,
}

/// Why a position could not be resolved.
pub(crate) type PositionError = String;

/// Resolve `pos`; `entities` gives the reference entities of relative positions.
pub(crate) fn resolve(pos: &Position, net: Option<&RoadNetwork>, entities: &[Entity]) -> Result<Placement, PositionError> {
    resolve_with_route(pos, net, entities, None, None)
}

/// [`resolve`] for a position an action puts its entity at: a relative road or lane position
/// moves along the entity's own route first, else along its reference entity's (esmini's
/// TeleportAction copies the entity's route into the position, Position::EvaluateRelation).
pub(crate) fn resolve_with_route(
    pos: &Position,
    net: Option<&RoadNetwork>,
    entities: &[Entity],
    own_route: Option<&routing::Route>,
    random: Option<&mut crate::esmini_random::EsminiRandom>,
) -> Result<Placement, PositionError> {
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
                    Ok(Placement { x, y, z: z.map(|z| z + o.z), h, lane: None, world_left: false, h_rel: None })
                }
                None => Ok(Placement { x: *x, y: *y, z: *z, h, lane: None, world_left: false, h_rel: None }),
            }
        }
        Position::RelativeWorld { entity, dx, dy, dz, orientation } => {
            let e = find(entity)?;
            let h = orient(e.h, orientation.as_ref());
            Ok(Placement { x: e.x + dx, y: e.y + dy, z: dz.map(|d| e.z + d), h, lane: None, world_left: false, h_rel: None })
        }
        Position::RelativeObject { entity, dx, dy, dz, orientation } => {
            let e = find(entity)?;
            let h = orient(e.h, orientation.as_ref());
            // esmini's Position::EvaluateRelation (RELATIVE_OBJECT) turns (dx, dy, dz) by the
            // entity's whole attitude, heading, pitch and roll (RotateVec3d): on a banked or
            // sloped road the offsets shrink horizontally.
            let (pitch, roll) = net.map_or((0.0, 0.0), |n| crate::attitude::surface_pitch_roll(n, e));
            // rel_pos_->GetH(): the heading esmini's position holds (EvaluateHPR: along ±y the
            // gimbal guard turns it 1e-6 rad), so a dx along ±y lands dx·1e-6 aside. (The guard
            // alone: elsewhere the held heading differs from `e.h` in its last bits only.)
            let h_rel_pos = crate::entities::esmini_reported_heading(e.h);
            let [vx, vy, vz] = rotate_hpr(h_rel_pos, pitch, roll, [*dx, *dy, dz.unwrap_or(0.0)]);
            Ok(Placement { x: e.x + vx, y: e.y + vy, z: dz.map(|_| e.z + vz), h, lane: None, world_left: false, h_rel: None })
        }
        Position::Lane { road_id, lane_id, s, offset, orientation } => {
            let net = net.ok_or("a LanePosition needs a road network")?;
            let road = crate::roads::road_id::resolve_road_id(net, road_id).ok_or_else(|| format!("unknown road `{road_id}`"))?;
            lane_placement(net, road, *lane_id, *s, *offset, orientation.as_ref())
        }
        Position::Road { road_id, s, t, orientation } => {
            let net = net.ok_or("a RoadPosition needs a road network")?;
            let road = crate::roads::road_id::resolve_road_id(net, road_id).ok_or_else(|| format!("unknown road `{road_id}`"))?;
            let mut p = road_placement(net, road, *s, *t, orientation.as_ref())?;
            // esmini's OSCPositionRoad: the heading is relative to the road's reference direction
            // on either side of the road (a LanePosition's to the lane's direction) unless an
            // absolute orientation gives h; without an orientation (or without h) it is the
            // road's direction itself, so on a lane driving against s the entity faces +s.
            face_along_road(net, &mut p, orientation.as_ref());
            Ok(p)
        }
        Position::RelativeRoad { entity, ds, dt, orientation } => {
            let net = net.ok_or("a RelativeRoadPosition needs a road network")?;
            crate::relative_position::relative_road(net, find(entity)?, *ds, *dt, orientation.as_ref(), own_route, random)
        }
        Position::RelativeLane { entity, d_lane, ds, ds_lane, offset, orientation } => {
            let net = net.ok_or("a RelativeLanePosition needs a road network")?;
            let along = crate::relative_position::Along::of(*ds, *ds_lane);
            crate::relative_position::relative_lane(net, find(entity)?, *d_lane, along, *offset, orientation.as_ref(), own_route, random)
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
pub(crate) fn relative_heading(o: Option<&Orientation>) -> Orientation {
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

pub(crate) fn place(
    net: &RoadNetwork,
    road: usize,
    lane_id: i32,
    s: f64,
    offset: f64,
    along: bool,
    o: Option<&Orientation>,
) -> Result<Placement, PositionError> {
    let mut lp = LanePos { road, lane_id, s, offset, dir: if along { 1.0 } else { -1.0 } };
    let pose = lp.pose(net).ok_or("lane missing")?;
    let facing = lp.facing_heading(&pose);
    // A relative heading also turns by the lane centre's drift atan(dt/ds) (esmini's
    // EvaluateHPR: h_road + h_relative + GetHOffset), as a lane follower's heading does.
    let drift = lane_drift(net, road, lane_id, s);
    let h = match o {
        Some(Orientation { reference: Some(ReferenceContext::Absolute), h: Some(h), .. }) => *h,
        // A relative heading is taken from the road's reference direction, as esmini does.
        Some(Orientation { h: Some(h), .. }) => pose.road_heading + h + if along { 0.0 } else { PI } + drift,
        _ => facing + drift,
    };
    // Facing the other way than the lane's direction makes the entity drive against s.
    let rel = wrap(h - pose.road_heading);
    lp.dir = if rel.abs() <= std::f64::consts::FRAC_PI_2 + 1e-9 { 1.0 } else { -1.0 };
    Ok(Placement { x: pose.x, y: pose.y, z: Some(pose.z), h, lane: Some(lp), world_left: false, h_rel: None })
}

/// Face `p` as esmini faces a road position (OSCPositionRoad, a RELATIVE_ROAD position): an
/// absolute h as it is, else relative to the road's reference direction (h, or 0 without one).
pub(crate) fn face_along_road(net: &RoadNetwork, p: &mut Placement, orientation: Option<&Orientation>) {
    match orientation {
        Some(Orientation { reference: Some(ReferenceContext::Absolute), h: Some(_), .. }) => {}
        o => turn_from_road_direction(net, p, o.and_then(|o| o.h).unwrap_or(0.0)),
    }
}

/// The drift atan(dt/ds) of the centre of lane `lane_id` of road `road` at `s` (esmini's
/// Position::GetHOffset; 0 for a road that does not exist).
pub(crate) fn lane_drift(net: &RoadNetwork, road: usize, lane_id: i32, s: f64) -> f64 {
    net.roads.get(road).map_or(0.0, |r| crate::roads::lane_slope::drift_angle(r, r.section_index_at(s), lane_id, s))
}

/// Face `p` at `h` from its road's reference direction (plus the lane's drift, as esmini's
/// relative headings); the lane direction it drives follows.
pub(crate) fn turn_from_road_direction(net: &RoadNetwork, p: &mut Placement, h: f64) {
    let Some(lp) = p.lane.as_mut() else { return };
    let Some(pose) = lp.pose(net) else { return };
    p.h = pose.road_heading + h + lane_drift(net, lp.road, lp.lane_id, lp.s);
    lp.dir = if wrap(h).abs() <= std::f64::consts::FRAC_PI_2 + 1e-9 { 1.0 } else { -1.0 };
}

/// Placement at road coordinates (s, t): attached to the lane esmini's Track2Lane picks, the
/// driving lane containing t or else the nearest one (`lane_snap`), at the offset that keeps t.
pub(crate) fn road_placement(net: &RoadNetwork, road: usize, s: f64, t: f64, o: Option<&Orientation>) -> Result<Placement, PositionError> {
    let r = net.roads.get(road).ok_or("road missing")?;
    let s = s.clamp(0.0, r.length);
    let section = r.section_index_at(s);
    let (lane_id, offset) = crate::roads::lane_snap::snap(r, section, s, t, false).unwrap_or((0, t - r.lane_offset_at(s)));
    let along = drives_along_s(r.rule, lane_id);
    place(net, road, lane_id, s, offset, along, o)
}

/// `v` turned by heading `h`, pitch `p` and roll `r` (esmini's RotateVec3d: Rz(h)·Ry(p)·Rx(r);
/// its guard against gimbal lock, which moves a result by at most a micrometre per metre, is
/// left out). With no pitch and roll it is the plain turn by h.
fn rotate_hpr(h: f64, p: f64, r: f64, v: [f64; 3]) -> [f64; 3] {
    let (sh, ch) = h.sin_cos();
    if p == 0.0 && r == 0.0 {
        return [v[0] * ch - v[1] * sh, v[0] * sh + v[1] * ch, v[2]];
    }
    let (sp, cp) = p.sin_cos();
    let (sr, cr) = r.sin_cos();
    [
        ch * cp * v[0] + (ch * sp * sr - sh * cr) * v[1] + (sh * sr + ch * sp * cr) * v[2],
        sh * cp * v[0] + (ch * cr + sh * sp * sr) * v[1] + (sh * sp * cr - ch * sr) * v[2],
        -sp * v[0] + cp * sr * v[1] + cp * cr * v[2],
    ]
}

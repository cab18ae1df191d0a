//! Positions.

use super::trajectory::{read_route_ref, read_trajectory_ref};
use super::Reader;
use crate::attr::Cx;
use crate::error::{Error, ErrorKind};
use crate::model::*;
use crate::xml::Elem;

/// Reads a `Position` wrapper element (or any element whose first child is the position).
pub(crate) fn read_position(r: &mut Reader, cx: &Cx, wrapper: &Elem) -> Result<Position, Error> {
    let e = cx.choice(wrapper, "a position")?;
    read_position_kind(r, cx, e)
}

/// An Orientation without a `type` takes its file's default, as esmini reads it
/// (ScenarioReader::parseOSCOrientation): absolute up to OpenSCENARIO 1.2, relative from 1.3
/// (the standard's 1.3 default).
fn orientation(cx: &Cx, e: &Elem) -> Result<Option<Orientation>, Error> {
    e.child("Orientation")
        .map(|o| {
            let reference = match cx.opt_enum(o, "type")? {
                Some(kind) => Some(kind),
                None => match cx.record.rev_minor.get() {
                    Some(minor) if minor <= 2 => Some(ReferenceContext::Absolute),
                    Some(_) => Some(ReferenceContext::Relative),
                    None => None,
                },
            };
            Ok(Orientation { reference, h: cx.opt_f64(o, "h")?, p: cx.opt_f64(o, "p")?, r: cx.opt_f64(o, "r")? })
        })
        .transpose()
}

pub(crate) fn lane_id(cx: &Cx, e: &Elem, name: &str) -> Result<i32, Error> {
    let v = cx.i64(e, name)?;
    if let Some(a) = e.attr(name) {
        cx.site(name, &v.to_string(), a.pos);
    }
    i32::try_from(v).map_err(|_| cx.err(ErrorKind::Value, e.pos, format!("lane id {v} is out of range")))
}

pub(crate) fn read_position_kind(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Position, Error> {
    Ok(match e.name.as_str() {
        "WorldPosition" => Position::World {
            x: cx.f64(e, "x")?,
            y: cx.f64(e, "y")?,
            z: cx.opt_f64(e, "z")?,
            h: cx.opt_f64(e, "h")?,
            p: cx.opt_f64(e, "p")?,
            r: cx.opt_f64(e, "r")?,
        },
        // the two share their attributes; only the frame of (dx, dy, dz) differs
        "RelativeWorldPosition" | "RelativeObjectPosition" => {
            let entity = cx.reference(e, "entityRef")?;
            let (dx, dy, dz) = (cx.f64(e, "dx")?, cx.f64(e, "dy")?, cx.opt_f64(e, "dz")?);
            let orientation = orientation(cx, e)?;
            if e.name == "RelativeWorldPosition" {
                Position::RelativeWorld { entity, dx, dy, dz, orientation }
            } else {
                Position::RelativeObject { entity, dx, dy, dz, orientation }
            }
        }
        "RoadPosition" => Position::Road { road_id: cx.reference(e, "roadId")?, s: cx.f64(e, "s")?, t: cx.f64(e, "t")?, orientation: orientation(cx, e)? },
        "RelativeRoadPosition" => {
            Position::RelativeRoad { entity: cx.reference(e, "entityRef")?, ds: cx.f64(e, "ds")?, dt: cx.f64(e, "dt")?, orientation: orientation(cx, e)? }
        }
        "LanePosition" => Position::Lane {
            road_id: cx.reference(e, "roadId")?,
            lane_id: lane_id(cx, e, "laneId")?,
            s: cx.f64(e, "s")?,
            offset: cx.f64_or(e, "offset", 0.0)?,
            orientation: orientation(cx, e)?,
        },
        "RelativeLanePosition" => {
            let ds = cx.opt_f64(e, "ds")?;
            let ds_lane = cx.opt_f64(e, "dsLane")?;
            Position::RelativeLane {
                entity: cx.reference(e, "entityRef")?,
                d_lane: i32::try_from(cx.i64(e, "dLane")?).map_err(|_| cx.err(ErrorKind::Value, e.pos, "dLane is out of range"))?,
                ds: if ds.is_none() && ds_lane.is_none() { Some(0.0) } else { ds },
                ds_lane,
                offset: cx.f64_or(e, "offset", 0.0)?,
                orientation: orientation(cx, e)?,
            }
        }
        "RoutePosition" => {
            let route = read_route_ref(r, cx, cx.child(e, "RouteRef")?)?;
            let irp = cx.child(e, "InRoutePosition")?;
            let c = cx.choice(irp, "FromCurrentEntity, FromRoadCoordinates or FromLaneCoordinates")?;
            let in_route = match c.name.as_str() {
                "FromCurrentEntity" | "PositionOfCurrentEntity" => InRoutePosition::FromCurrentEntity { entity: cx.reference(c, "entityRef")? },
                "FromRoadCoordinates" | "PositionInRoadCoordinates" => InRoutePosition::FromRoadCoordinates { path_s: cx.f64(c, "pathS")?, t: cx.f64(c, "t")? },
                "FromLaneCoordinates" | "PositionInLaneCoordinates" => InRoutePosition::FromLaneCoordinates {
                    path_s: cx.f64(c, "pathS")?,
                    lane_id: lane_id(cx, c, "laneId")?,
                    lane_offset: cx.f64_or(c, "laneOffset", 0.0)?,
                },
                _ => return Err(cx.unexpected(c, "InRoutePosition", "FromCurrentEntity, FromRoadCoordinates, FromLaneCoordinates")),
            };
            Position::Route { route: Box::new(route), orientation: orientation(cx, e)?, in_route }
        }
        "GeoPosition" => Position::Geo {
            latitude_deg: match cx.opt_f64(e, "latitudeDeg")? {
                Some(v) => v,
                None => cx.f64(e, "latitude")?.to_degrees(),
            },
            longitude_deg: match cx.opt_f64(e, "longitudeDeg")? {
                Some(v) => v,
                None => cx.f64(e, "longitude")?.to_degrees(),
            },
            altitude: match cx.opt_f64(e, "altitude")? {
                Some(v) => Some(v),
                None => cx.opt_f64(e, "height")?,
            },
            orientation: orientation(cx, e)?,
        },
        "TrajectoryPosition" => Position::Trajectory {
            trajectory: Box::new(read_trajectory_ref(r, cx, cx.child(e, "TrajectoryRef")?)?),
            s: cx.f64(e, "s")?,
            t: cx.opt_f64(e, "t")?,
            orientation: orientation(cx, e)?,
        },
        _ => {
            return Err(cx.unexpected(
                e,
                "Position",
                "WorldPosition, RelativeWorldPosition, RelativeObjectPosition, RoadPosition, RelativeRoadPosition, \
                 LanePosition, RelativeLanePosition, RoutePosition, GeoPosition, TrajectoryPosition",
            ))
        }
    })
}

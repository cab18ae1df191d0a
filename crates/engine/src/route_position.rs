//! Routes at run time: planning an OpenSCENARIO route on the road network (its waypoints
//! resolved from the run's current state) and RoutePosition, a place given in route
//! coordinates (path s along the route with a lane and offset, or a lateral t) or as where an
//! entity currently is.

use crate::entities::Entity;
use crate::positions::{lane_placement, resolve, road_placement, Placement, PositionError};
use opendrive::RoadNetwork;
use openscenario::{InRoutePosition, Orientation, Route, RouteStrategy};
use routing::{Strategy, Waypoint};

fn strategy(s: RouteStrategy) -> Strategy {
    match s {
        RouteStrategy::Fastest => Strategy::Fastest,
        RouteStrategy::Shortest => Strategy::Shortest,
        RouteStrategy::LeastIntersections => Strategy::LeastIntersections,
        RouteStrategy::Random => Strategy::Random,
    }
}

/// A waypoint for a placement on a lane: its road, lane, s and the way it faces.
pub(crate) fn waypoint_of(p: &Placement) -> Option<Waypoint> {
    let lp = p.lane?;
    Some(Waypoint { road: lp.road, lane: lp.lane_id, s: lp.s, along_s: Some(lp.dir > 0.0) })
}

/// Plan `route`; its waypoints are resolved against `entities` as they are now.
pub(crate) fn plan_route(route: &Route, net: &RoadNetwork, entities: &[Entity]) -> Result<routing::Route, String> {
    let mut wps = Vec::with_capacity(route.waypoints.len());
    let mut strategies = Vec::with_capacity(route.waypoints.len());
    for (i, w) in route.waypoints.iter().enumerate() {
        let p = resolve(&w.position, Some(net), entities).map_err(|e| format!("waypoint {i}: {e}"))?;
        let wp = waypoint_of(&p).ok_or_else(|| format!("waypoint {i} is not on a lane"))?;
        wps.push(wp);
        strategies.push(strategy(w.strategy));
    }
    routing::Route::plan(net, &wps, &strategies, route.closed).map_err(|e| e.to_string())
}

pub(crate) fn route_placement(
    route: &Route,
    in_route: &InRoutePosition,
    orientation: Option<&Orientation>,
    net: Option<&RoadNetwork>,
    entities: &[Entity],
) -> Result<Placement, PositionError> {
    let net = net.ok_or("a RoutePosition needs a road network")?;
    if let InRoutePosition::FromCurrentEntity { entity } = in_route {
        let e = entities.iter().find(|e| &e.name == entity).ok_or_else(|| format!("unknown entity `{entity}`"))?;
        return Ok(Placement { x: e.x, y: e.y, z: Some(e.z), h: e.h, lane: e.lane });
    }
    let planned = crate::position_cache::route(route, || plan_route(route, net, entities)).map_err(|e| format!("route `{}`: {e}", route.name))?;
    let (path_s, lane, offset, t) = match in_route {
        InRoutePosition::FromLaneCoordinates { path_s, lane_id, lane_offset } => (*path_s, Some(*lane_id), *lane_offset, 0.0),
        InRoutePosition::FromRoadCoordinates { path_s, t } => (*path_s, None, 0.0, *t),
        InRoutePosition::FromCurrentEntity { .. } => (0.0, None, 0.0, 0.0),
    };
    let rp = planned.locate(path_s).ok_or("route position outside the route")?;
    // Facing the route's direction of travel unless an orientation says otherwise.
    let mut p = match lane {
        Some(l) => lane_placement(net, rp.road, l, rp.s, offset, orientation)?,
        None => road_placement(net, rp.road, rp.s, t, orientation)?,
    };
    if orientation.is_none() {
        if let Some(lp) = p.lane.as_mut() {
            let want = if rp.along_s { 1.0 } else { -1.0 };
            if lp.dir != want {
                lp.dir = want;
                if let Some(pose) = lp.pose(net) {
                    p.h = lp.facing_heading(&pose);
                }
            }
        }
    }
    Ok(p)
}

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

/// The waypoint of `pos`, resolved as placement `p`: its road, lane, s and the way it faces.
/// A placement given in the world (a WorldPosition, a position relative to an entity) is
/// attached to a road as esmini attaches every waypoint (Position::SetInertiaPos →
/// XYZ2TrackPos): the lane of the driving types containing the point, else the nearest one
/// (`lane_snap`); it faces as its heading says when the position gives one, else the lane's
/// driving direction (Route::AddWaypoint: a first waypoint without a heading takes it).
pub(crate) fn waypoint_of(pos: &openscenario::Position, p: &Placement, net: &RoadNetwork) -> Option<Waypoint> {
    if let Some(lp) = p.lane {
        return Some(Waypoint { road: lp.road, lane: lp.lane_id, s: lp.s, along_s: Some(lp.dir > 0.0) });
    }
    let at = crate::roads::locate::world_to_lane(net, p.x, p.y, None)?;
    let road = net.roads.get(at.road)?;
    let lane = crate::roads::lane_snap::snap(road, at.section, at.s, at.t, false).map_or(at.lane_id, |(id, _)| id);
    let along_s = trajectory::gives_heading(pos).then(|| crate::angles::wrap(p.h - at.heading).abs() <= std::f64::consts::FRAC_PI_2 + 1e-9);
    Some(Waypoint { road: at.road, lane, s: at.s, along_s })
}

/// Plan `route`; its waypoints are resolved against `entities` as they are now.
pub(crate) fn plan_route(route: &Route, net: &RoadNetwork, entities: &[Entity]) -> Result<routing::Route, String> {
    let mut wps = Vec::with_capacity(route.waypoints.len());
    let mut strategies = Vec::with_capacity(route.waypoints.len());
    for (i, w) in route.waypoints.iter().enumerate() {
        let p = resolve(&w.position, Some(net), entities).map_err(|e| format!("waypoint {i}: {e}"))?;
        let wp = waypoint_of(&w.position, &p, net).ok_or_else(|| format!("waypoint {i} is not on a road"))?;
        wps.push(wp);
        strategies.push(strategy(w.strategy));
    }
    // Waypoints in a row on one road are travelled in the order of their s, whichever way
    // their lanes drive or they face (esmini's Route::CalculcateWPDirWrtWP; RoadPath measures
    // the leg as the difference of s).
    for i in 0..wps.len() {
        let prev = i.checked_sub(1).and_then(|j| wps.get(j)).filter(|p| p.road == wps[i].road).map(|p| wps[i].s >= p.s);
        let next = wps.get(i + 1).filter(|n| n.road == wps[i].road).map(|n| n.s >= wps[i].s);
        if let Some(along) = prev.or(next) {
            wps[i].along_s = Some(along);
        }
    }
    routing::Route::plan(net, &wps, &strategies, route.closed).map_err(|e| e.to_string())
}

/// Where a RoutePosition puts an entity, as esmini 3.6 resolves it (ScenarioReader's
/// RoutePosition branch, OSCPositionRoute::SetRouteRefLaneCoord/SetRouteRefRoadCoord,
/// Position::SetRouteLanePosition/SetRouteRoadPosition, Route::SetPathS):
/// - the place is the route's road and s at `pathS`, with the lane id (or t) as written — the
///   route's direction does not mirror it; a `pathS` outside [0, route length], or a route
///   esmini finds no way along, leaves the route at its first waypoint (SetPathS returns before
///   moving it); a path s its anchors carry beyond the last waypoint goes on along the last
///   road up to its end (`past_route_end`);
/// - the heading is the road's reference direction turned by a relative angle, never the
///   route's direction of travel: FromLaneCoordinates without an orientation turns by π on a
///   lane with a positive id (whatever the traffic rule), with one by its h, plus π where the
///   lane it lands on drives against s (Position::GetDrivingDirectionRelativeRoad, traffic rule
///   considered); FromRoadCoordinates turns by the orientation's h or 0. The orientation's type
///   is not read (absolute is taken as relative);
/// - FromRoadCoordinates' t is read as an integer (ScenarioReader's strtoi: 2.6 is 2);
/// - a lane the road does not have there leaves the position where a new one is, the world
///   origin, turned by the angle above taken on lane 0 (Position::SetLanePosMode fails before
///   Track2XYZ and before it sets the lane id), yet with the road, s and offset set: moving
///   goes on from lane 0 there;
/// - FromCurrentEntity is not implemented by esmini: its position is the world origin, heading 0.
pub(crate) fn route_placement(
    route: &Route,
    in_route: &InRoutePosition,
    orientation: Option<&Orientation>,
    net: Option<&RoadNetwork>,
    entities: &[Entity],
) -> Result<Placement, PositionError> {
    resolve_route(route, in_route, orientation, net, entities).map(|(p, _)| p)
}

/// What esmini 3.6 does with a RoutePosition where it differs from the standard (see
/// `route_placement`), to be said where an action uses it.
pub(crate) fn esmini_deviation(pos: &openscenario::Position, net: Option<&RoadNetwork>, entities: &[Entity]) -> Option<String> {
    let openscenario::Position::Route { route, in_route, orientation } = pos else { return None };
    resolve_route(route, in_route, orientation.as_ref(), net, entities).ok().and_then(|(_, note)| note)
}

/// The world origin, where esmini leaves a position it could not set.
fn origin(h: f64) -> Placement {
    Placement { x: 0.0, y: 0.0, z: Some(0.0), h, lane: None, world_left: false, h_rel: None }
}

fn resolve_route(
    route: &Route,
    in_route: &InRoutePosition,
    orientation: Option<&Orientation>,
    net: Option<&RoadNetwork>,
    entities: &[Entity],
) -> Result<(Placement, Option<String>), PositionError> {
    let net = net.ok_or("a RoutePosition needs a road network")?;
    let mut notes = Vec::new();
    let (path_s, lane, offset, t) = match in_route {
        InRoutePosition::FromCurrentEntity { entity } => {
            let note = format!(
                "RoutePosition FromCurrentEntity (`{entity}`) is not implemented by esmini 3.6: the position is the world origin, heading 0, as esmini has it"
            );
            return Ok((origin(0.0), Some(note)));
        }
        InRoutePosition::FromLaneCoordinates { path_s, lane_id, lane_offset } => (*path_s, Some(*lane_id), *lane_offset, 0.0),
        InRoutePosition::FromRoadCoordinates { path_s, t } => {
            if t.fract() != 0.0 {
                notes.push(format!("RoutePosition FromRoadCoordinates t = {t} is read as {}, an integer, as esmini 3.6 reads it", t.trunc()));
            }
            (*path_s, None, 0.0, t.trunc())
        }
    };
    let planned = crate::position_cache::route(route, || plan_route(route, net, entities));
    // esmini counts path s from its route anchors (route_anchors.rs).
    let mapped = planned.as_ref().ok().and_then(|p| {
        let roads = waypoint_roads(route, net, entities)?;
        crate::route_anchors::true_path_s(net, p, &roads, path_s)
    });
    let (road, s) = match planned {
        Ok(planned) => {
            let (true_s, length) = mapped.unwrap_or((path_s, planned.length()));
            if (0.0..=length).contains(&path_s) {
                let rp = planned.locate(true_s).ok_or("route position outside the route")?;
                past_route_end(net, &planned, true_s).unwrap_or((rp.road, rp.s))
            } else {
                notes.push(format!(
                    "RoutePosition pathS = {path_s} lies outside route `{}` (0 to {length:.3} m): the position is the route's first waypoint, as in esmini 3.6",
                    route.name
                ));
                first_waypoint(route, net, entities)?
            }
        }
        Err(e) => {
            notes.push(format!("route `{}`: {e}; the RoutePosition is its first waypoint, as in esmini 3.6", route.name));
            first_waypoint(route, net, entities)?
        }
    };
    let h = orientation.and_then(|o| o.h);
    let placed = match lane {
        Some(l) => lane_placement(net, road, l, s, offset, None),
        None => road_placement(net, road, s, t, None),
    };
    let mut p = match placed {
        Ok(p) => p,
        Err(e) => {
            // The failed position keeps lane id 0, which drives along s: an orientation's h
            // is not turned.
            let turn = match (lane, h) {
                (Some(l), None) if l > 0 => std::f64::consts::PI,
                (_, h) => h.unwrap_or(0.0),
            };
            notes.push(format!("RoutePosition: {e}; the position is the world origin, as esmini 3.6 leaves it"));
            // Position::SetLanePosMode has set road and s (SetLongitudinalTrackPos) and the
            // offset before it finds the lane missing; its lane id stays 0. The world point is
            // not recomputed (no Track2XYZ), but the default controller moves the entity on from
            // those road coordinates: lane 0, the RoutePosition's offset.
            let mut p = origin(turn);
            p.world_left = true;
            p.h_rel = Some(turn);
            p.lane = (lane.is_some() && road < net.roads.len()).then_some(crate::roads::lane_position::LanePos {
                road,
                lane_id: 0,
                s,
                offset,
                dir: if turn.cos() >= 0.0 { 1.0 } else { -1.0 },
            });
            return Ok((p, Some(notes.join("; "))));
        }
    };
    let turn = match (lane, h) {
        (Some(l), None) if l > 0 => std::f64::consts::PI,
        (Some(_), Some(h)) => {
            let lane_id = p.lane.map_or(0, |lp| lp.lane_id);
            h + if lane_drives_against_s(net, road, lane_id) { std::f64::consts::PI } else { 0.0 }
        }
        (_, h) => h.unwrap_or(0.0),
    };
    crate::positions::turn_from_road_direction(net, &mut p, turn);
    Ok((p, (!notes.is_empty()).then(|| notes.join("; "))))
}

/// Whether `lane` of `road` drives against s (esmini's GetDrivingDirectionRelativeRoad < 0).
fn lane_drives_against_s(net: &RoadNetwork, road: usize, lane: i32) -> bool {
    net.roads.get(road).is_some_and(|r| !opendrive::drives_along_s(r.rule, lane))
}

/// The road of each of the route's waypoints, resolved as planning resolves them.
fn waypoint_roads(route: &Route, net: &RoadNetwork, entities: &[Entity]) -> Option<Vec<usize>> {
    route.waypoints.iter().map(|w| resolve(&w.position, Some(net), entities).ok().and_then(|p| waypoint_of(&w.position, &p, net)).map(|wp| wp.road)).collect()
}

/// The road and s of a route's first waypoint (esmini's route before SetPathS moves it). A
/// LanePosition on a lane its road does not have there still gives its road and s: esmini's
/// Position::SetLanePosMode sets both (SetLongitudinalTrackPos) before it finds the lane
/// Where Route::SetPathS puts a path s that lands beyond the planned route's end (esmini's
/// anchors count short after a dropped waypoint, `route_anchors`, so a path s within its route
/// length can): it goes on past the last waypoint along the last road, from where the route
/// enters it, by what is left, and Position::SetLanePos holds s within that road's ends
/// ("Unexpected: local_s … out of range"): not the last waypoint but the road's end.
fn past_route_end(net: &RoadNetwork, planned: &routing::Route, true_s: f64) -> Option<(usize, f64)> {
    let over = true_s - planned.length();
    if over <= 0.0 || planned.is_closed() {
        return None;
    }
    let end = planned.locate(planned.length())?;
    let length = net.roads.get(end.road)?.length;
    let s = if end.along_s { end.s + over } else { end.s - over };
    Some((end.road, s.clamp(0.0, length)))
}

/// missing, and Route::AddWaypoint keeps that waypoint (with lane id 0).
fn first_waypoint(route: &Route, net: &RoadNetwork, entities: &[Entity]) -> Result<(usize, f64), PositionError> {
    let w = route.waypoints.first().ok_or_else(|| format!("route `{}` has no waypoint", route.name))?;
    let p = match resolve(&w.position, Some(net), entities) {
        Ok(p) => p,
        Err(e) => {
            if let openscenario::Position::Lane { road_id, s, .. } = &w.position {
                if let Some(road) = crate::roads::road_id::resolve_road_id(net, road_id) {
                    let length = net.roads.get(road).map_or(0.0, |r| r.length);
                    return Ok((road, s.clamp(0.0, length)));
                }
            }
            return Err(format!("route `{}`, waypoint 0: {e}", route.name));
        }
    };
    let wp = waypoint_of(&w.position, &p, net).ok_or_else(|| format!("route `{}`: waypoint 0 is not on a road", route.name))?;
    Ok((wp.road, wp.s))
}

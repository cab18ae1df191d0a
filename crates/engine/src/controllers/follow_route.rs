//! esmini's FollowRoute controller (`ControllerFollowRoute`): once the entity has a route, a
//! lane-independent path (`lane_router`) to the next scenario waypoint gives one waypoint per
//! road; near a waypoint on another lane of its road the entity changes lane by a sinusoidal
//! LaneChangeAction over `laneChangeTime` (during which the default controller leaves it
//! alone), unless another vehicle nearer than `minDistForCollision` is in the way. Passing a
//! waypoint narrows the route the default controller follows at junctions to (here, next
//! waypoint); missing one plans again. After the last waypoint the controller deactivates and
//! drops the route; with `testMode` the entity also stops. Always additive: storyboard actions
//! keep acting on the entity. Stepped after the default controller, as esmini steps its
//! controllers.

pub(crate) mod state;

use state::FollowRouteRt;

use super::lane_router::{calculate_path, connected_lane_at_s, connecting_lane_id, next_roads, path_waypoints, LaneSpot};
use crate::actions::lane_change::state::LaneChangeRt;
use crate::dynamics::{sign, Transition};
use crate::roads::lane_geometry::{lane_borders, lane_center_t};
use crate::sim::Sim;
use opendrive::{ContactPoint, ElementType, RoadNetwork};
use openscenario::{Controller, DynamicsDimension, DynamicsShape};
use routing::Strategy;
use std::sync::Arc;

/// esmini's SMALL_NUMBER (CommonMini.hpp: 1e-6).
const SMALL: f64 = crate::dynamics::ESMINI_SMALL_NUMBER;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum WaypointStatus {
    Passed,
    Missed,
    NotReached,
}

impl FollowRouteRt {
    pub(crate) fn new(c: &Controller) -> Self {
        // esmini reads the numbers with strtod: text that is no number is 0.
        let num = |n: &str, default: f64| c.properties.get(n).map_or(default, |v| v.trim().parse::<f64>().unwrap_or(0.0));
        FollowRouteRt {
            active: false,
            longitudinal: false,
            lane_change_time: num("laneChangeTime", 5.0),
            min_dist_for_collision: num("minDistForCollision", 10.0),
            min_lane_width: 0.5,
            test_mode: c.properties.get("testMode") == Some("true"),
            scenario: Vec::new(),
            route_roads: Vec::new(),
            path_calculated: false,
            waypoints: Vec::new(),
            current: 0,
            scenario_index: 0,
            changing_lane: false,
            lane_change: None,
            lane_change_placed: false,
        }
    }

    /// esmini's `Activate`: start over (the path is planned at the next step with a route).
    pub(crate) fn activate(&mut self, longitudinal: bool) {
        self.active = true;
        self.longitudinal = longitudinal;
        self.current = 0;
        self.scenario_index = 0;
        self.path_calculated = false;
        self.changing_lane = false;
        self.waypoints.clear();
        self.lane_change = None;
    }

    /// A route was assigned: its scenario waypoints and the roads it passes, in order.
    pub(crate) fn set_route(&mut self, scenario: Vec<(LaneSpot, Strategy)>, route_roads: Vec<usize>) {
        self.scenario = scenario;
        self.route_roads = route_roads;
    }

    /// Whether a running lane change holds the entity (esmini's override mode).
    pub(crate) fn holds_entity(&self) -> bool {
        self.active && self.lane_change.is_some()
    }

    /// Whether it owns the longitudinal domain now: esmini's `ChangeLane` puts the controller
    /// in override mode from the start of its lane change to the end (additive otherwise), and
    /// `Object::IsControllerModeOnDomains(MODE_OVERRIDE, DOMAIN_MASK_LONG)` asks for a
    /// controller active on that domain.
    pub(crate) fn overrides_longitudinal(&self) -> bool {
        self.holds_entity() && self.longitudinal
    }

    /// Whether it is active on the longitudinal domain (it operates on both; `longitudinal`
    /// says whether its activation asked for this one).
    pub(crate) fn active_longitudinal(&self) -> bool {
        self.active && self.longitudinal
    }
}

/// esmini's route waypoints for `route` through `scenario` waypoints, as Route::AddWaypoint
/// keeps them: the roads of every waypoint added (`all_waypoints_`: each scenario waypoint's
/// road and, between two, each road the planned route passes), and the scenario waypoints the
/// controller steers to (`scenario_waypoints_`). Before adding a waypoint AddWaypoint drops
/// the last anchor (`minimal_waypoints_`) when the new waypoint is on its road, or when the
/// first two anchors share a road, and with it the last scenario waypoint (while more than
/// one is left); `all_waypoints_` keeps every one.
pub(crate) fn route_waypoints(route: &routing::Route, scenario: &[(LaneSpot, Strategy)]) -> (Vec<usize>, Vec<(LaneSpot, Strategy)>) {
    let mut all = Vec::new();
    let mut minimal: Vec<usize> = Vec::new();
    let mut kept = Vec::with_capacity(scenario.len());
    for (i, &(w, strategy)) in scenario.iter().enumerate() {
        let n = minimal.len();
        if n > 1 && ((n == 2 && minimal[0] == minimal[1]) || minimal[n - 1] == w.road) {
            minimal.pop();
            if kept.len() > 1 {
                kept.pop();
            }
        }
        if i > 0 {
            let (from, to) = (route.waypoint_route_s(i - 1), route.waypoint_route_s(i));
            if let (Some(a), Some(b)) = (from, to) {
                let mut last = scenario[i - 1].0.road;
                for leg in route.legs().iter().filter(|l| l.route_s >= a && l.route_s < b) {
                    if leg.road != last && leg.road != w.road {
                        all.push(leg.road);
                        minimal.push(leg.road);
                    }
                    last = leg.road;
                }
            }
        }
        all.push(w.road);
        minimal.push(w.road);
        kept.push((w, strategy));
    }
    (all, kept)
}

/// The lane position esmini's controller sees: during its lane change esmini keeps the entity
/// on the target lane with an offset (the trace's lane_id says so) until the change ends.
/// LatLaneChangeAction::Start leaves the entity on its own lane; its first Step at speed moves it.
fn route_lane(sim: &Sim, e: usize, f: &FollowRouteRt) -> Option<crate::roads::LanePos> {
    f.lane_change.as_ref().filter(|_| f.lane_change_placed).map(|l| l.internal).or_else(|| sim.entities.get(e).and_then(|en| en.lane))
}

/// esmini's `Position::GetDrivingDirectionRelativeRoad`: whether traffic in the entity's lane
/// drives along s (the lane's side and the road's rule, not the way the entity faces).
fn lane_drives_along_s(net: &RoadNetwork, lp: &crate::roads::LanePos) -> bool {
    net.roads.get(lp.road).is_none_or(|r| opendrive::drives_along_s(r.rule, lp.lane_id))
}

/// Where an entity is, as a lane spot, and whether it drives along s.
fn spot_of(lp: &crate::roads::LanePos) -> (LaneSpot, bool) {
    (LaneSpot { road: lp.road, lane: lp.lane_id, s: lp.s }, lp.dir > 0.0)
}

impl<'a> Sim<'a> {
    /// A route was assigned to entity `e`: a FollowRoute controller of it keeps the route's
    /// scenario waypoints (resolved now) and the roads between them.
    pub(crate) fn tell_route_follower(&mut self, e: usize, route: &openscenario::Route, planned: &routing::Route) {
        if !self.controllers_of(e).any(|c| matches!(c, super::state::ControllerRt::FollowRoute(_))) {
            return;
        }
        let Some(net) = self.net else { return };
        let mut scenario = Vec::with_capacity(route.waypoints.len());
        for w in &route.waypoints {
            // A waypoint given in the world is attached to a road as the route attaches it
            // (Route::AddWaypoint: Position::XYZ2TrackPos).
            let Ok(p) = crate::positions::resolve(&w.position, Some(net), &self.entities) else { return };
            let Some(wp) = crate::route_position::waypoint_of(&w.position, &p, net) else { return };
            let strategy = match w.strategy {
                openscenario::RouteStrategy::Fastest => Strategy::Fastest,
                openscenario::RouteStrategy::Shortest => Strategy::Shortest,
                openscenario::RouteStrategy::LeastIntersections => Strategy::LeastIntersections,
                openscenario::RouteStrategy::Random => Strategy::Random,
            };
            scenario.push((LaneSpot { road: wp.road, lane: wp.lane, s: wp.s }, strategy));
        }
        self.give_route_follower(e, scenario, planned);
    }

    /// esmini's AcquirePositionAction makes a route of (where the entity is, the target): a
    /// FollowRoute controller follows it like an assigned one.
    pub(crate) fn tell_route_follower_waypoints(&mut self, e: usize, waypoints: &[routing::Waypoint], planned: &routing::Route) {
        let scenario = waypoints.iter().map(|w| (LaneSpot { road: w.road, lane: w.lane, s: w.s }, Strategy::Shortest)).collect();
        self.give_route_follower(e, scenario, planned);
    }

    fn give_route_follower(&mut self, e: usize, scenario: Vec<(LaneSpot, Strategy)>, planned: &routing::Route) {
        let (roads, kept) = route_waypoints(planned, &scenario);
        let follower = self.controller_of_mut(e, |c| if let super::state::ControllerRt::FollowRoute(f) = c { Some(f) } else { None });
        if let Some(f) = follower {
            f.set_route(kept, roads);
        }
    }

    /// esmini's `ControllerFollowRoute::Step`, after the default controller
    /// (`step_controllers_in_order`).
    pub(super) fn step_follow_route(&mut self, e: usize, f: &mut FollowRouteRt, _dt: f64) {
        let Some(net) = self.net else { return };
        if self.entities[e].route.is_none() || f.scenario.is_empty() {
            return;
        }
        if !f.path_calculated {
            self.calculate_waypoints(net, e, f);
            if !f.active {
                return;
            }
        }
        let Some(next) = f.waypoints.get(f.current).copied() else {
            self.deactivate_follow_route(e, f);
            return;
        };
        let Some(vehicle) = route_lane(self, e, f) else { return };
        let speed = self.entities[e].speed;
        let mut created = false;
        if next.road == vehicle.road {
            let connected = connected_lane_at_s(net, vehicle.road, vehicle.lane_id, vehicle.s, next.s);
            let same_lane = next.lane == vehicle.lane_id || connected == next.lane;
            let dist_to_change = (f.lane_change_time * speed).max(25.0);
            let near = (vehicle.s - next.s).abs() < dist_to_change;
            if !same_lane && near && self.can_change_lane(net, e, f, next.lane) {
                // esmini starts the action in this step (after the default controller moved the
                // entity) and steps it from the next one on, instead of the default controller.
                if let Some(lc) = self.new_route_lane_change(net, e, next.lane, f.lane_change_time) {
                    f.lane_change = Some(lc);
                    f.lane_change_placed = false;
                    created = true;
                    // LatLaneChangeAction::Start (ControllerFollowRoute::ChangeLane, this step)
                    // aligns the entity to the road at once: SetHeadingRelativeRoadDirection(0).
                    if let Some(en) = self.entities.get_mut(e) {
                        en.align_with_lane(net);
                    }
                }
                f.changing_lane = true;
            }
        }
        if !created {
            if let Some(mut lc) = f.lane_change.take() {
                if self.entities.get(e).is_some_and(|en| en.speed.abs() >= crate::dynamics::ESMINI_SMALL_NUMBER) {
                    f.lane_change_placed = true;
                }
                if self.step_lane_change(e, &mut lc) {
                    f.changing_lane = false;
                } else {
                    f.lane_change = Some(lc);
                }
            }
        }
        self.update_waypoints(net, e, f, vehicle, next);
    }

    /// esmini's `CreateLaneChange` + `LatLaneChangeAction::Start`: a sinusoidal change over
    /// `time` seconds to the centre of lane `lane`.
    fn new_route_lane_change(&self, net: &RoadNetwork, e: usize, lane: i32, time: f64) -> Option<LaneChangeRt> {
        let lp = self.entities.get(e)?.lane?;
        let road = net.roads.get(lp.road)?;
        let s = lp.s.clamp(0.0, road.length);
        let (cur_c, tgt_c) = (lane_center_t(road, lp.lane_id, s)?, lane_center_t(road, lane, s)?);
        let offset_in_target = cur_c + lp.offset - tgt_c;
        let internal = crate::roads::LanePos { lane_id: lane, offset: offset_in_target, ..lp };
        let lane_sign = sign(f64::from(lane));
        let mut t = Transition::new(DynamicsShape::Sinusoidal, DynamicsDimension::Time, time);
        t.set_start(lane_sign * offset_in_target);
        t.set_target(0.0);
        Some(LaneChangeRt { transition: t, internal, missing_lane_sign: None })
    }

    /// esmini's `CanChangeLane`: not while changing lane; the lane must exist here, be wide
    /// enough, and no other vehicle on this side of the road within `minDistForCollision`
    /// may be in a lane between (a check that is off when that distance is not positive).
    fn can_change_lane(&self, net: &RoadNetwork, e: usize, f: &FollowRouteRt, lane: i32) -> bool {
        if f.changing_lane {
            return false;
        }
        let Some(me) = self.entities.get(e) else { return false };
        let Some(lp) = me.lane else { return false };
        let Some(road) = net.roads.get(lp.road) else { return false };
        let section = road.section_index_at(lp.s);
        if road.lane_sections.get(section).and_then(|sec| sec.lane(lane)).is_none() {
            return false;
        }
        if f.min_dist_for_collision <= 0.0 {
            return true;
        }
        let width = lane_borders(road, section, lane, lp.s).map_or(0.0, |b| b.width());
        if width < f.min_lane_width {
            return false;
        }
        for (i, other) in self.entities.iter().enumerate() {
            let Some(op) = other.lane else { continue };
            let same_road = op.road == lp.road;
            let same_lane = op.lane_id == lp.lane_id;
            if i == e || !other.active || (same_road && same_lane) {
                continue;
            }
            let close = (me.x - other.x).hypot(me.y - other.y) < f.min_dist_for_collision;
            let same_side = op.lane_id.signum() == lp.lane_id.signum();
            if close && same_side && same_road {
                // esmini lists the lanes from the next one towards the other vehicle up to its
                // lane, so any such vehicle blocks.
                let (lo, hi) = (lp.lane_id.min(op.lane_id), lp.lane_id.max(op.lane_id));
                if op.lane_id != lp.lane_id && (lo..=hi).contains(&op.lane_id) {
                    return false;
                }
            }
        }
        true
    }

    /// esmini's `CalculateWaypoints`: plan from where the entity is to the next scenario
    /// waypoint (the one after the entity's road on the route, when that road is on it).
    fn calculate_waypoints(&mut self, net: &RoadNetwork, e: usize, f: &mut FollowRouteRt) {
        let Some(lp) = route_lane(self, e, f) else { return };
        let (start, forward) = spot_of(&lp);
        let n = f.scenario.len();
        let mut j = 0;
        for (i, &road) in f.route_roads.iter().enumerate() {
            if f.scenario.get(j).is_some_and(|(w, _)| w.road == road) {
                j += 1;
            }
            if road == start.road {
                // The scenario waypoint on this road (the last detailed one) counts only while
                // it is still ahead.
                let last_s = if i + 1 == f.route_roads.len() { f.scenario.last().map(|(w, _)| w.s) } else { None };
                // esmini asks the lane's driving direction here, not the entity's heading.
                let along = lane_drives_along_s(net, &lp);
                let ahead = match last_s {
                    None => true,
                    Some(ws) => (along && start.s < ws - SMALL) || (!along && start.s > ws + SMALL),
                };
                if ahead {
                    f.scenario_index = j.min(n - 1);
                    break;
                }
            }
        }
        let Some(&(target, strategy)) = f.scenario.get(f.scenario_index) else { return };
        let path = calculate_path(net, start, forward, target, strategy);
        if path.is_empty() {
            self.deactivate_follow_route(e, f);
            return;
        }
        f.waypoints = path_waypoints(net, &path, start, target);
        if let (Some(a), Some(b)) = (f.waypoints.first().copied(), f.waypoints.get(1).copied()) {
            self.narrow_route(net, e, a, b, forward);
        }
        f.path_calculated = true;
    }

    /// esmini's `Route::ReplaceMinimalWaypoints`: the route the default controller follows at
    /// junctions becomes the way from `a` to `b`.
    fn narrow_route(&mut self, net: &RoadNetwork, e: usize, a: LaneSpot, b: LaneSpot, forward: bool) {
        // Route::CalculcateWPDirWrtWP gives the first waypoint a direction only when its road
        // is the second's or links to it directly (Road::IsPredecessor / IsSuccessor: a road
        // link, or a junction connection from it to that road). Without one the route is
        // broken: Route::SetPathS fails at waypoint 0 on every move.
        let linked = a.road == b.road || [ContactPoint::Start, ContactPoint::End].iter().any(|&c| next_roads(net, (a.road, c)).contains(&b.road));
        if !linked {
            if let Some(en) = self.entities.get_mut(e) {
                en.route_broken = true;
            }
            return;
        }
        let from = routing::Waypoint { road: a.road, lane: a.lane, s: a.s, along_s: Some(forward) };
        let to = routing::Waypoint { road: b.road, lane: b.lane, s: b.s, along_s: None };
        if let Ok(r) = routing::Route::plan(net, &[from, to], &[Strategy::Shortest, Strategy::Shortest], false) {
            if let Some(en) = self.entities.get_mut(e) {
                en.set_route(Some(Arc::new(r)));
            }
        }
    }

    /// esmini's `UpdateWaypoints`, with the entity where it was before this step's lane change.
    fn update_waypoints(&mut self, net: &RoadNetwork, e: usize, f: &mut FollowRouteRt, vehicle: crate::roads::LanePos, next: LaneSpot) {
        match waypoint_status(net, &vehicle, &next) {
            WaypointStatus::Passed => {
                f.current += 1;
                if f.waypoints.last().is_some_and(|w| w.road == next.road) {
                    if f.scenario_index + 1 < f.scenario.len() {
                        f.scenario_index += 1;
                        f.path_calculated = false;
                        self.calculate_waypoints(net, e, f);
                        f.current = 0;
                    }
                    return;
                }
                let (v, forward) = spot_of(&vehicle);
                if let Some(w) = f.waypoints.get(f.current).copied() {
                    self.narrow_route(net, e, v, w, forward);
                }
            }
            WaypointStatus::Missed => {
                if self.entities[e].route.is_some() {
                    f.path_calculated = false;
                    self.calculate_waypoints(net, e, f);
                    f.current = 0;
                }
            }
            WaypointStatus::NotReached => {}
        }
    }

    /// esmini's `ControllerFollowRoute::Deactivate`: drop the route; stop in test mode.
    pub(super) fn deactivate_follow_route(&mut self, e: usize, f: &mut FollowRouteRt) {
        if let Some(en) = self.entities.get_mut(e) {
            if f.test_mode {
                // Object::SetSpeed marks the speed as set: prepareGroundTruth does not take
                // the step's displacement (a lane change's jump) as speed instead.
                en.speed = 0.0;
                en.speed_set = true;
            }
            en.set_route(None);
            en.controller_active = false;
        }
        f.active = false;
    }
}

/// esmini's `GetWaypointStatus`: on the waypoint's road, at or past its s: passed when on its
/// lane, else missed; on the road after it, passed when the entity's lane leads back to the
/// waypoint's lane, else missed; otherwise not reached. "Past" and "after" follow the driving
/// direction of the entity's lane (GetDrivingDirectionRelativeRoad), whichever way it faces:
/// an entity put into a lane of the other direction has missed its waypoint at once.
fn waypoint_status(net: &RoadNetwork, vehicle: &crate::roads::LanePos, wp: &LaneSpot) -> WaypointStatus {
    let forward = lane_drives_along_s(net, vehicle);
    let same_lane = wp.lane == vehicle.lane_id;
    if wp.road == vehicle.road {
        let past = (forward && vehicle.s > wp.s - SMALL) || (!forward && vehicle.s < wp.s + SMALL);
        return match (past, same_lane) {
            (true, true) => WaypointStatus::Passed,
            (true, false) => WaypointStatus::Missed,
            (false, _) => WaypointStatus::NotReached,
        };
    }
    // The link behind the entity: where it came from.
    let behind = if forward { ContactPoint::Start } else { ContactPoint::End };
    let Some(rl) = net.roads.get(vehicle.road).and_then(|r| r.link_at(behind)) else { return WaypointStatus::NotReached };
    let before: Vec<usize> = match rl.element_type {
        ElementType::Road | ElementType::Junction => next_roads(net, (vehicle.road, behind)),
    };
    if !before.contains(&wp.road) {
        return WaypointStatus::NotReached;
    }
    let previous_lane = connecting_lane_id(net, (vehicle.road, behind), vehicle.lane_id, wp.road);
    if previous_lane == wp.lane {
        WaypointStatus::Passed
    } else {
        WaypointStatus::Missed
    }
}

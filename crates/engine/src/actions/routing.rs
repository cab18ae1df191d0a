//! AssignRouteAction and AcquirePositionAction: both give the entity a route (the second from
//! where it is to the target position) and complete at once; the route then decides which
//! way the entity goes at junctions (see `roads::road_follow`).

use super::ActionRt;
use crate::positions::resolve;
use crate::route_position::{plan_route, waypoint_of};
use crate::sim::Sim;
use openscenario::{Position, Route};
use std::sync::Arc;

impl<'a> Sim<'a> {
    pub(super) fn assign_route(&mut self, slot: usize, e: usize, route: &Route) -> ActionRt {
        let Some(net) = self.net else {
            self.warn_action(slot, "AssignRouteAction needs a road network".into());
            return ActionRt::Done;
        };
        match plan_route(route, net, &self.entities) {
            Ok(r) => {
                for w in &r.warnings {
                    let msg = format!("route `{}`: {w}", route.name);
                    self.warn_action(slot, msg);
                }
                self.tell_route_follower(e, route, &r);
                if let Some(en) = self.entities.get_mut(e) {
                    en.set_route(Some(Arc::new(r)));
                }
            }
            // esmini's Route::AddWaypoint marks a route without a way between two waypoints
            // invalid, CheckValid then drops its waypoints, and AssignRouteAction::Start still
            // gives the entity that empty route: it replaces the route it had.
            Err(msg) => {
                self.warn_action(
                    slot,
                    format!(
                        "AssignRouteAction: route `{}` cannot be planned: {msg}; as in esmini, the entity drops the route it had and drives on without one",
                        route.name
                    ),
                );
                if let Some(en) = self.entities.get_mut(e) {
                    en.set_route(None);
                }
            }
        }
        ActionRt::Done
    }

    pub(super) fn acquire_position(&mut self, slot: usize, e: usize, target: &Position) -> ActionRt {
        let Some(net) = self.net else {
            self.warn_action(slot, "AcquirePositionAction needs a road network".into());
            return ActionRt::Done;
        };
        let Some(en) = self.entities.get(e) else { return ActionRt::Done };
        let from = en.lane.map(|lp| routing::Waypoint { road: lp.road, lane: lp.lane_id, s: lp.s, along_s: Some(lp.dir > 0.0) });
        let to = resolve(target, Some(net), &self.entities).ok().and_then(|p| waypoint_of(target, &p, net));
        let (Some(from), Some(to)) = (from, to) else {
            self.warn_action(slot, "AcquirePositionAction: the entity or the target is not on a lane".into());
            return ActionRt::Done;
        };
        let strategies = [routing::Strategy::Shortest, routing::Strategy::Shortest];
        let mut planned = routing::Route::plan(net, &[from, to], &strategies, false);
        // esmini's RoadPath::Calculate joins two waypoints on one road by their s difference,
        // whichever way that runs (behind the entity too): the route is that road alone and
        // crosses no junction, where the entity then takes its lane's first connection
        // (Position::MoveToConnectingRoad with a valid route). A route of that road alone:
        if from.road == to.road && planned.as_ref().map_or(true, |r| r.legs().iter().any(|l| l.road != from.road)) {
            planned = routing::Route::plan(net, &[from, from], &strategies, false);
        }
        match planned {
            Ok(r) => {
                self.tell_route_follower_waypoints(e, &[from, to], &r);
                if let Some(en) = self.entities.get_mut(e) {
                    en.set_route(Some(Arc::new(r)));
                }
            }
            Err(msg) => {
                self.warn_action(slot, format!("AcquirePositionAction: no route to the target: {msg}"));
                // The action's route replaces the old one even so; invalid, it is ignored
                // (Route::CheckValid), as if the entity had none.
                if let Some(en) = self.entities.get_mut(e) {
                    en.set_route(None);
                }
            }
        }
        ActionRt::Done
    }
}

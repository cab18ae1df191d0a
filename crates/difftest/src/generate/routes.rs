//! Routes: two to four waypoints along a walk of the lane graph from a place (through
//! junctions where the map has them), each with a routing strategy (shortest, fastest,
//! leastIntersections, random), given as Lane, Road or World positions; and the
//! RoutePositions on them — FromLaneCoordinates on a lane of either driving direction (esmini
//! turns an entity on a positive lane id round), FromRoadCoordinates (whole and fractional t:
//! esmini reads t as an integer) and FromCurrentEntity.

use super::lanes::{along, lanes_at, walk, walk_length, Leg, Place};
use super::positions::Scope;
use super::{f3, Gen};

/// A route the generator wrote: its XML and the walk it follows from its first waypoint.
pub(crate) struct Route {
    pub xml: String,
    pub legs: Vec<Leg>,
}

impl Gen<'_> {
    /// A route starting at `from`, about `length` metres long.
    pub(crate) fn route_from(&mut self, from: Place, length: f64) -> Route {
        let legs = walk(&self.map.net, from, length, &mut self.rng);
        let total = walk_length(&legs);
        let n = if total < 20.0 { 2 } else { self.pick(&[2, 2, 3, 4]) };
        let mut dists: Vec<f64> = (1..n).map(|_| self.num(0.15 * total, total.max(0.16 * total))).collect();
        dists.sort_by(f64::total_cmp);
        if let Some(last) = dists.last_mut() {
            *last = (total - 1.0).max(*last);
        }
        let name = self.unique("Route");
        let mut waypoints = String::new();
        let roads = legs.iter().map(|l| l.road).collect::<std::collections::BTreeSet<_>>().len();
        if roads > 1 {
            self.feature("route:several-roads");
        }
        if legs.iter().any(|l| self.map.net.roads.get(l.road).is_some_and(|r| r.junction.is_some())) {
            self.feature("route:through-junction");
        }
        self.feature(if from.forward { "route:start-along-s" } else { "route:start-against-s" });
        for (k, d) in std::iter::once(0.0).chain(dists).enumerate() {
            let p = along(&legs, d).unwrap_or(from);
            let strategy = self.pick(&["shortest", "fastest", "leastIntersections", "random"]);
            self.feature(format!("route:strategy/{strategy}"));
            let position = if k == 0 { self.lane_position_xml(&p, 0.0, "") } else { self.place_position(&p, "route:waypoint/", Scope::Plain, false) };
            waypoints.push_str(&format!(r#"<Waypoint routeStrategy="{strategy}"><Position>{position}</Position></Waypoint>"#));
        }
        Route { xml: format!(r#"<Route name="{name}" closed="false"><ParameterDeclarations/>{waypoints}</Route>"#), legs }
    }

    /// A RoutePosition on a route through (or near) `place`, and the feature it names.
    pub(crate) fn route_position_at(&mut self, place: &Place, prefix: &str) -> String {
        self.feature(format!("{prefix}RoutePosition"));
        // start the route a little before the place, so that the place is on it at path_s
        let back = self.num(0.0, 60.0);
        let start = Place { s: if place.forward { place.s - back } else { place.s + back }, ..*place };
        let len = self.map.net.roads.get(place.road).map_or(0.0, |r| r.length);
        let start = Place { s: start.s.clamp(0.5, (len - 0.5).max(0.5)), ..start };
        let path_s = (place.s - start.s).abs();
        let extra = self.num(50.0, 250.0);
        let route = self.route_from(start, path_s + extra);
        let at = along(&route.legs, path_s).unwrap_or(*place);
        let kind = self.pick(&["FromLaneCoordinates", "FromLaneCoordinates", "FromRoadCoordinates", "FromCurrentEntity"]);
        let kind = if kind == "FromCurrentEntity" && (self.entities.is_empty() || !self.chance(0.3)) { "FromLaneCoordinates" } else { kind };
        let in_route = match kind {
            "FromRoadCoordinates" => {
                let r = &self.map.net.roads[at.road];
                let t = r.lane_center_t(r.section_index_at(at.s), at.lane, at.s).unwrap_or(0.0);
                let t = if self.chance(0.5) {
                    self.feature(format!("{prefix}RoutePosition/FromRoadCoordinates/t-whole"));
                    t.round()
                } else {
                    self.feature(format!("{prefix}RoutePosition/FromRoadCoordinates/t-fractional"));
                    (t * 100.0).round() / 100.0
                };
                format!(r#"<FromRoadCoordinates pathS="{}" t="{t}"/>"#, f3(path_s))
            }
            "FromCurrentEntity" => {
                let names = self.names();
                let e = names[self.pick_index(names.len())].clone();
                self.feature(format!("{prefix}RoutePosition/FromCurrentEntity"));
                format!(r#"<FromCurrentEntity entityRef="{e}"/>"#)
            }
            _ => {
                // a lane of either driving direction at that point of the route
                let lanes = lanes_at(&self.map.net, at.road, at.s);
                let (lane, lane_along_s) = if lanes.is_empty() { (at.lane, at.forward) } else { lanes[self.pick_index(lanes.len())] };
                let with_route = lane_along_s == at.forward;
                self.feature(format!("{prefix}RoutePosition/FromLaneCoordinates/lane-{}", if with_route { "with-route" } else { "against-route" }));
                self.feature(format!("{prefix}RoutePosition/FromLaneCoordinates/lane-id-{}", if lane > 0 { "positive" } else { "negative" }));
                let offset = if self.chance(0.3) { self.num(-0.6, 0.6) } else { 0.0 };
                format!(r#"<FromLaneCoordinates pathS="{}" laneId="{lane}" laneOffset="{offset}"/>"#, f3(path_s))
            }
        };
        let orientation = if self.chance(0.15) {
            self.feature(format!("{prefix}RoutePosition/orientation"));
            r#"<Orientation type="relative" h="0"/>"#
        } else {
            ""
        };
        format!(r#"<RoutePosition><RouteRef>{}</RouteRef>{orientation}<InRoutePosition>{in_route}</InRoutePosition></RoutePosition>"#, route.xml)
    }

    /// An AssignRouteAction for entity `actor`: its route starts a little ahead of where the
    /// entity starts (esmini's route followers plan from the entity to the next waypoint and
    /// refuse one on the entity's own road and lane behind it).
    pub(crate) fn assign_route_action(&mut self, actor: &str) -> String {
        let from = self.place_ahead(actor, 5.0, 30.0);
        let len = self.num(150.0, 600.0);
        let route = self.route_from(from, len);
        format!("<PrivateAction><RoutingAction><AssignRouteAction>{}</AssignRouteAction></RoutingAction></PrivateAction>", route.xml)
    }
}

//! A planned route: the lanes driven, in order, and queries in route coordinates.

use crate::error::Error;
use crate::search::{Point, Rules, Search, Step};
use crate::waypoint::{Strategy, Waypoint};
use opendrive::{drives_along_s, ContactPoint, LaneRef, RoadNetwork};

/// Most waypoints accepted for one route (hostile input).
pub const MAX_WAYPOINTS: usize = 10_000;

/// A stretch of one lane of one lane section driven in one direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leg {
    pub road: usize,
    pub section: usize,
    pub lane: i32,
    pub along_s: bool,
    /// Road s where the stretch starts and ends (s_end < s_start when driven against s).
    pub s_start: f64,
    pub s_end: f64,
    /// Route s at `s_start`.
    pub route_s: f64,
    /// The lane this stretch was changed into from (a lane change at `s_start`).
    pub lane_change_from: Option<i32>,
}

impl Leg {
    pub fn length(&self) -> f64 {
        (self.s_end - self.s_start).abs()
    }
}

/// A point of the route in road coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoutePoint {
    pub road: usize,
    pub lane: i32,
    pub s: f64,
    pub along_s: bool,
    /// Index of the leg in [`Route::legs`].
    pub leg: usize,
}

/// The road a route continues on, the lane it enters and the end it enters at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NextRoad {
    pub road: usize,
    pub lane: i32,
    pub contact: ContactPoint,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Route {
    legs: Vec<Leg>,
    length: f64,
    closed: bool,
    /// Route s of each waypoint (the closing return to the first is not repeated).
    waypoint_s: Vec<f64>,
    /// The first waypoint: where a route of zero length is.
    start: RoutePoint,
    /// Some waypoint asked for the `random` strategy; it was planned as `shortest`.
    pub random_as_shortest: bool,
    /// Things a user should know: relaxed rules needed to find a leg, and the like.
    pub warnings: Vec<String>,
}

fn check_waypoint(net: &RoadNetwork, i: usize, w: &Waypoint) -> Result<Point, Error> {
    let bad = |reason: String| Error::BadWaypoint { index: i, reason };
    let r = net.roads.get(w.road).ok_or_else(|| bad(format!("no road with index {}", w.road)))?;
    if !w.s.is_finite() {
        return Err(bad(format!("s = {} is not a finite number", w.s)));
    }
    let s = w.s.clamp(0.0, r.length);
    let section = r.section_index_at(s);
    if r.lane_sections.get(section).and_then(|sec| sec.lane(w.lane)).is_none() || w.lane == 0 {
        return Err(bad(format!("road `{}` has no lane {} at s = {s}", r.id, w.lane)));
    }
    let along_s = w.along_s.unwrap_or_else(|| drives_along_s(r.rule, w.lane));
    Ok(Point { lane: LaneRef { road: w.road, section, lane: w.lane }, along_s, s })
}

impl Route {
    /// Plan a route through `waypoints`. `strategies[i]` is the strategy of waypoint i and
    /// rules the leg that reaches it (missing entries: shortest). A closed route returns
    /// from the last waypoint to the first. If no leg obeys driving directions and the
    /// target lane, the search retries with any lane of the target's road, then without
    /// driving directions, then entering the target's road from a lane that does not continue
    /// into it (as esmini's route finds its way), with a warning.
    pub fn plan(net: &RoadNetwork, waypoints: &[Waypoint], strategies: &[Strategy], closed: bool) -> Result<Route, Error> {
        if waypoints.len() > MAX_WAYPOINTS {
            return Err(Error::TooManyWaypoints { max: MAX_WAYPOINTS, found: waypoints.len() });
        }
        if waypoints.len() < 2 {
            return Err(Error::TooFewWaypoints { found: waypoints.len() });
        }
        let points = waypoints.iter().enumerate().map(|(i, w)| check_waypoint(net, i, w)).collect::<Result<Vec<_>, _>>()?;
        let p0 = points[0];
        let start = RoutePoint { road: p0.lane.road, lane: p0.lane.lane, s: p0.s, along_s: p0.along_s, leg: 0 };
        let mut route = Route { legs: Vec::new(), length: 0.0, closed, waypoint_s: vec![0.0], start, random_as_shortest: false, warnings: Vec::new() };
        let extra_kind =
            net.roads.get(waypoints[0].road).and_then(|r| r.lane_sections.get(points[0].lane.section)).and_then(|s| s.lane(waypoints[0].lane)).map(|l| l.kind);
        let mut order: Vec<usize> = (1..points.len()).collect();
        if closed {
            order.push(0);
        }
        let mut at = points[0];
        let mut from_i = 0usize;
        for to_i in order {
            let strategy = strategies.get(to_i).copied().unwrap_or(Strategy::Shortest);
            if strategy == Strategy::Random {
                route.random_as_shortest = true;
            }
            let target = points[to_i];
            let mut found = None;
            let tries = [
                (Rules { obey_direction: true, exact_target: true, lane_free_target_entry: false }, None),
                (Rules { obey_direction: true, exact_target: false, lane_free_target_entry: false }, Some("reached on another lane of its road")),
                (Rules { obey_direction: false, exact_target: false, lane_free_target_entry: false }, Some("reached only against a lane's driving direction")),
                (
                    Rules { obey_direction: false, exact_target: false, lane_free_target_entry: true },
                    Some("reached only from a lane that does not continue into its road (esmini's route takes that way)"),
                ),
            ];
            for (rules, note) in tries {
                let search = Search { net, strategy, rules, extra_kind };
                if let Some(r) = search.run(at, &target) {
                    if let Some(n) = note {
                        route.warnings.push(format!("route: waypoint {to_i} {n}"));
                    }
                    found = Some(r);
                    break;
                }
            }
            let road_id = |p: &Point| net.roads.get(p.lane.road).map(|r| r.id.clone()).unwrap_or_default();
            let Some((steps, s_goal)) = found else {
                return Err(Error::NoPath { from: from_i, to: to_i, from_road: road_id(&at), to_road: road_id(&target) });
            };
            route.append(net, &steps, s_goal);
            if let Some(last) = steps.last() {
                at = Point { lane: last.key.lane, along_s: last.key.along_s, s: s_goal };
            }
            if to_i != 0 {
                route.waypoint_s.push(route.length);
            }
            from_i = to_i;
        }
        Ok(route)
    }

    fn append(&mut self, net: &RoadNetwork, steps: &[Step], s_goal: f64) {
        // The lane a chain of lane changes started from.
        let mut change_from: Option<i32> = None;
        for (i, st) in steps.iter().enumerate() {
            let k = st.key;
            let next_is_change = steps.get(i + 1).is_some_and(|n| n.lane_change);
            let s_end = match steps.get(i + 1) {
                // A lane change happens at this state's entry: nothing is driven in it.
                Some(_) if next_is_change => st.entry_s,
                Some(_) => {
                    let (s0, s1) = net.roads.get(k.lane.road).and_then(|r| r.section_range(k.lane.section)).unwrap_or((st.entry_s, st.entry_s));
                    if k.along_s {
                        s1
                    } else {
                        s0
                    }
                }
                None => s_goal,
            };
            if next_is_change && change_from.is_none() {
                change_from = Some(k.lane.lane);
            }
            let mut leg = Leg {
                road: k.lane.road,
                section: k.lane.section,
                lane: k.lane.lane,
                along_s: k.along_s,
                s_start: st.entry_s,
                s_end,
                route_s: self.length,
                lane_change_from: None,
            };
            if leg.length() <= 0.0 {
                continue;
            }
            if st.lane_change {
                leg.lane_change_from = change_from.take();
            }
            self.length += leg.length();
            self.legs.push(leg);
        }
    }

    pub fn legs(&self) -> &[Leg] {
        &self.legs
    }
    /// Total length (m) along the lanes driven; lane changes count no length.
    pub fn length(&self) -> f64 {
        self.length
    }
    pub fn is_closed(&self) -> bool {
        self.closed
    }
    /// Route s of waypoint `i`.
    pub fn waypoint_route_s(&self, i: usize) -> Option<f64> {
        self.waypoint_s.get(i).copied()
    }

    /// Road coordinates of route s (wrapped on a closed route, clamped on an open one). A
    /// route of zero length (waypoints at one spot) is its first waypoint, with leg 0.
    pub fn locate(&self, route_s: f64) -> Option<RoutePoint> {
        if !route_s.is_finite() {
            return None;
        }
        if self.legs.is_empty() {
            return Some(self.start);
        }
        let rs = if self.closed && self.length > 0.0 { route_s.rem_euclid(self.length) } else { route_s.clamp(0.0, self.length) };
        let i = self.legs.partition_point(|l| l.route_s <= rs).saturating_sub(1);
        let leg = self.legs.get(i)?;
        let d = (rs - leg.route_s).clamp(0.0, leg.length());
        let s = if leg.along_s { leg.s_start + d } else { leg.s_start - d };
        Some(RoutePoint { road: leg.road, lane: leg.lane, s, along_s: leg.along_s, leg: i })
    }

    /// Route s of road position (road, s): among the legs covering it, the first at or
    /// after `near` (a route s, e.g. the entity's last one), else the first overall.
    pub fn route_s_of(&self, road: usize, s: f64, near: Option<f64>) -> Option<f64> {
        let hits = self
            .legs
            .iter()
            .filter(|l| l.road == road && s >= l.s_start.min(l.s_end) - 1e-9 && s <= l.s_start.max(l.s_end) + 1e-9)
            .map(|l| l.route_s + (s - l.s_start).abs().min(l.length()));
        let all: Vec<f64> = hits.collect();
        match near {
            Some(n) => all.iter().copied().find(|&r| r >= n - 1e-9).or_else(|| all.first().copied()),
            None => all.first().copied(),
        }
    }

    /// The road after `road` when driven in direction `along_s`: the first leg on `road` in
    /// that direction, then the next leg on another road (wrapping on a closed route).
    pub fn next_road_after(&self, road: usize, along_s: bool) -> Option<NextRoad> {
        let i = self.legs.iter().position(|l| l.road == road && l.along_s == along_s)?;
        self.next_road_from_leg(i)
    }

    /// The road after the one driven at route s.
    pub fn next_road_after_s(&self, route_s: f64) -> Option<NextRoad> {
        let p = self.locate(route_s)?;
        self.next_road_from_leg(p.leg)
    }

    fn next_road_from_leg(&self, i: usize) -> Option<NextRoad> {
        let road = self.legs.get(i)?.road;
        let n = self.legs.len();
        let span = if self.closed { n } else { n - i };
        (1..span).map(|k| (i + k) % n).filter_map(|j| self.legs.get(j)).find(|l| l.road != road).map(|l| NextRoad {
            road: l.road,
            lane: l.lane,
            contact: if l.along_s { ContactPoint::Start } else { ContactPoint::End },
        })
    }
}

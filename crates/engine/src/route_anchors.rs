//! Route s as esmini counts it for a RoutePosition's `pathS`. esmini's Route keeps a list of
//! anchors (`minimal_waypoints_`: the scenario's waypoints and, between two of them, one on
//! every road passed, a third of the way along it), each with its own route s, and
//! Route::SetPathS finds a path s from the last anchor at or before it. Route::AddWaypoint
//! drops an anchor when the next waypoint is on its road (or when the first two waypoints share
//! a road), yet measures the route s of the anchors it then adds from the waypoint it dropped
//! (`all_waypoints_.back()`), not from the one the leg starts at: after a dropped waypoint the
//! anchors on the roads passed count short by the dropped stretch, and a path s there lands
//! that much further along the route. The planned route's own s is the true distance; this
//! maps esmini's path s onto it.

use opendrive::RoadNetwork;
use routing::Route;

/// Where esmini puts the anchor on a road a route passes (Route::AddWaypoint: a third of the
/// road's length from its start, `GetLength() * 0.33`).
const PASSED_ROAD_FRACTION: f64 = 0.33;

/// An anchor: its road, esmini's route s and the planned route's s at it.
#[derive(Debug, Clone, Copy)]
struct Anchor {
    road: usize,
    esmini_s: f64,
    true_s: f64,
}

/// esmini's anchors of `planned` (open routes only), given the road of each scenario waypoint.
fn anchors(net: &RoadNetwork, planned: &Route, waypoint_roads: &[usize]) -> Option<Vec<Anchor>> {
    let first = *waypoint_roads.first()?;
    let mut out = vec![Anchor { road: first, esmini_s: 0.0, true_s: 0.0 }];
    // The last waypoint esmini added (all_waypoints_.back()), dropped or not: its true s.
    let mut last_added = 0.0;
    for (k, &road) in waypoint_roads.iter().enumerate().skip(1) {
        let true_p = planned.waypoint_route_s(k)?;
        let n = out.len();
        if n > 1 && ((n == 2 && out[0].road == out[1].road) || out[n - 1].road == road) {
            out.pop();
        }
        let base = *out.last()?;
        let mut acc = base.esmini_s;
        for (r, true_mid) in passed_roads(net, planned, base, road, true_p) {
            acc += (true_mid - last_added).abs();
            last_added = true_mid;
            out.push(Anchor { road: r, esmini_s: acc, true_s: true_mid });
        }
        out.push(Anchor { road, esmini_s: base.esmini_s + (true_p - base.true_s), true_s: true_p });
        last_added = true_p;
    }
    Some(out)
}

/// The roads the route passes strictly between `base` and the waypoint on `road` at route s
/// `true_p`, each with the route s of its anchor.
fn passed_roads(net: &RoadNetwork, planned: &Route, base: Anchor, road: usize, true_p: f64) -> Vec<(usize, f64)> {
    let eps = 1e-9;
    let legs: Vec<_> = planned.legs().iter().filter(|l| l.route_s >= base.true_s - eps && l.route_s < true_p - eps && l.length() > 0.0).collect();
    let mut out: Vec<(usize, f64)> = Vec::new();
    let mut previous = base.road;
    for (i, leg) in legs.iter().enumerate() {
        if leg.road == previous || (leg.road == road && legs[i..].iter().all(|l| l.road == road)) {
            previous = leg.road;
            continue;
        }
        previous = leg.road;
        let Some(r) = net.roads.get(leg.road) else { continue };
        let s = r.length * PASSED_ROAD_FRACTION;
        // The stretch of this road's run that covers s, else the run's start.
        let run = legs[i..].iter().take_while(|l| l.road == leg.road);
        let hit = run.clone().find(|l| s >= l.s_start.min(l.s_end) - eps && s <= l.s_start.max(l.s_end) + eps).map(|l| l.route_s + (s - l.s_start).abs());
        out.push((leg.road, hit.unwrap_or(leg.route_s)));
    }
    out
}

/// The planned route's s at esmini's path s `path_s`, and esmini's route length (a path s
/// beyond it is off the route); `None` where the anchors cannot be told (a closed route, a
/// waypoint the plan does not have).
pub(crate) fn true_path_s(net: &RoadNetwork, planned: &Route, waypoint_roads: &[usize], path_s: f64) -> Option<(f64, f64)> {
    if planned.is_closed() {
        return None;
    }
    let a = anchors(net, planned, waypoint_roads)?;
    let length = a.last()?.esmini_s;
    // Route::SetPathS: the last anchor whose s is below path_s + 1e-6 (the first if none).
    let i = a.iter().take_while(|x| path_s > x.esmini_s - 1e-6).count().saturating_sub(1);
    let anchor = a.get(i)?;
    Some((anchor.true_s + (path_s - anchor.esmini_s), length))
}

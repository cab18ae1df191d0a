//! What a stretch of lane costs under each strategy, and which lanes a route may use.

use crate::waypoint::Strategy;
use opendrive::{LaneType, RoadNetwork};

/// Extra cost of one lane change, in metres of driving (shortest) or its time (fastest).
pub const LANE_CHANGE_COST_M: f64 = 30.0;

/// Speed assumed where neither the road type nor the lane gives a limit (50 km/h).
const DEFAULT_SPEED: f64 = 50.0 / 3.6;
/// Cost of entering a junction under `LeastIntersections`: more than any plausible distance.
const JUNCTION_PENALTY: f64 = 1.0e7;

/// Lane types a vehicle route may run through.
pub(crate) fn is_drivable(kind: LaneType) -> bool {
    kind.is_any_driving() || matches!(kind, LaneType::SlipLane | LaneType::Bus | LaneType::Taxi | LaneType::Hov)
}

/// Speed limit (m/s) of a lane at the start of its section: the lane's own speed record,
/// else the road type's, else 50 km/h.
fn speed(net: &RoadNetwork, road: usize, section: usize, lane: i32) -> f64 {
    let Some(r) = net.roads.get(road) else { return DEFAULT_SPEED };
    let Some(sec) = r.lane_sections.get(section) else { return DEFAULT_SPEED };
    let lane_speed = sec.lane(lane).and_then(|l| l.speeds.first()).and_then(|sp| sp.max_mps);
    let road_speed = r.type_at(sec.s).and_then(|t| t.speed.as_ref()).and_then(|sp| sp.max_mps);
    match lane_speed.or(road_speed) {
        Some(v) if v.is_finite() && v > 0.1 => v,
        _ => DEFAULT_SPEED,
    }
}

/// Cost of driving `dist` metres in the given lane.
pub(crate) fn drive(strategy: Strategy, net: &RoadNetwork, road: usize, section: usize, lane: i32, dist: f64) -> f64 {
    match strategy {
        Strategy::Fastest => dist / speed(net, road, section, lane),
        _ => dist,
    }
}

/// Cost of one lane change into `lane`.
pub(crate) fn lane_change(strategy: Strategy, net: &RoadNetwork, road: usize, section: usize, lane: i32) -> f64 {
    drive(strategy, net, road, section, lane, LANE_CHANGE_COST_M)
}

/// Extra cost of moving from `from` road onto `to` road.
pub(crate) fn transition(strategy: Strategy, net: &RoadNetwork, from: usize, to: usize) -> f64 {
    let in_junction = |r: usize| net.roads.get(r).is_some_and(|rd| rd.junction.is_some());
    if strategy == Strategy::LeastIntersections && in_junction(to) && !in_junction(from) {
        JUNCTION_PENALTY
    } else {
        0.0
    }
}

//! Roads and lanes the scenario's positions name, checked against the road network before a
//! run: a position on a road the map does not have, or in a lane its road does not have at
//! that `s`, refers to nothing. Like `openscenario::references`, these are problems the caller
//! turns into errors (the default) or warnings (`--lenient`); the run itself would leave such
//! an entity where it is.

use openscenario::{Position, Scenario};

use diagnostic::Diagnostic;

/// Every Road/Lane position of `scenario` whose road or lane `road` does not have.
pub fn road_references(scenario: &Scenario, road: Option<&opendrive::RoadNetwork>) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for (p, at) in openscenario::references::positions(scenario) {
        let (road_id, lane) = match p {
            Position::Road { road_id, .. } => (road_id, None),
            Position::Lane { road_id, lane_id, s, .. } => (road_id, Some((*lane_id, *s))),
            _ => continue,
        };
        let element = if lane.is_some() { "LanePosition" } else { "RoadPosition" };
        let Some(network) = road else {
            out.push(Diagnostic::at(at, format!("{element} on road `{road_id}`, but the scenario has no road network")));
            continue;
        };
        let Some(r) = network.road(road_id) else {
            out.push(Diagnostic::at(at, format!("{element}: road `{road_id}` is not in the road network")));
            continue;
        };
        if let Some((lane_id, s)) = lane {
            let exists = r.section_at(s).is_some_and(|sec| lane_id == 0 || sec.left.iter().chain(&sec.right).any(|l| l.id == lane_id));
            if !exists {
                out.push(Diagnostic::at(at, format!("LanePosition: road `{road_id}` has no lane {lane_id} at s = {s}")));
            }
        }
    }
    out
}

//! Roads, lanes and traffic signals the scenario names, checked against the road network before
//! a run: a position on a road the map does not have, or in a lane its road does not have at
//! that `s`, and a traffic signal (TrafficSignalStateAction, TrafficSignalCondition, a signal
//! controller's phase) the map does not have, refer to nothing. Like `openscenario::references`,
//! these are problems the caller turns into errors (the default) or warnings (`--lenient`),
//! each at the attribute that holds the name; the run itself would leave such an entity where
//! it is, or the signal without a state.

use std::collections::BTreeSet;

use openscenario::{ActionKind, ConditionKind, GlobalAction, Position, Scenario, ValueCondition};

use diagnostic::Diagnostic;

/// Every Road/Lane position of `scenario` whose road or lane `road` does not have, and every
/// traffic signal it names that `road` does not have.
pub fn road_references(scenario: &Scenario, road: Option<&opendrive::RoadNetwork>) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for (p, within) in openscenario::references::positions(scenario) {
        let (road_id, lane) = match p {
            Position::Road { road_id, .. } => (road_id, None),
            Position::Lane { road_id, lane_id, s, .. } => (road_id, Some((*lane_id, *s))),
            _ => continue,
        };
        let element = if lane.is_some() { "LanePosition" } else { "RoadPosition" };
        let at_road = || scenario.reference_site(within, "roadId", |v| v == road_id);
        let Some(network) = road else {
            out.push(Diagnostic::at(at_road(), format!("{element} on road `{road_id}`, but the scenario has no road network")));
            continue;
        };
        let Some(r) = crate::roads::road_id::resolve_road_id(network, road_id).and_then(|i| network.roads.get(i)) else {
            out.push(Diagnostic::at(at_road(), format!("{element}: road `{road_id}` is not in the road network")));
            continue;
        };
        if let Some((lane_id, s)) = lane {
            let exists = r.section_at(s).is_some_and(|sec| lane_id == 0 || sec.left.iter().chain(&sec.right).any(|l| l.id == lane_id));
            if !exists {
                let at_lane = scenario.reference_site(within, "laneId", |v| v == lane_id.to_string());
                out.push(Diagnostic::at(at_lane, format!("LanePosition: road `{road_id}` has no lane {lane_id} at s = {s}")));
            }
        }
    }
    if let Some(network) = road {
        signals(scenario, network, &mut out);
    }
    out
}

/// The traffic signals the scenario names that the road network does not have.
fn signals(scenario: &Scenario, network: &opendrive::RoadNetwork, out: &mut Vec<Diagnostic>) {
    let known: BTreeSet<&str> = network.roads.iter().flat_map(|r| &r.signals).map(|s| s.id.as_str()).collect();
    let mut check = |id: &str, within: &openscenario::Location, attribute: &str, what: &str| {
        if !known.contains(id) {
            let at = scenario.reference_site(within, attribute, |v| v == id);
            out.push(Diagnostic::at(at, format!("{what}: traffic signal `{id}` is not in the road network")));
        }
    };
    for c in &scenario.road_network.traffic_signal_controllers {
        for phase in &c.phases {
            for (id, _) in &phase.states {
                check(id, &c.origin, "trafficSignalId", &format!("TrafficSignalController `{}`, phase `{}`", c.name, phase.name));
            }
        }
    }
    openscenario::references::for_each_action(scenario, |a, _| {
        if let ActionKind::Global(GlobalAction::TrafficSignalState { name, .. }) = &a.kind {
            check(name, &a.origin, "name", "TrafficSignalStateAction");
        }
    });
    openscenario::references::for_each_condition(scenario, |c| {
        if let ConditionKind::ByValue(ValueCondition::TrafficSignal { name, .. }) = &c.kind {
            check(name, &c.origin, "name", "TrafficSignalCondition");
        }
    });
}

//! Traffic signals at run time: each signal's current state (signals are named by their
//! OpenDRIVE signal id, as in the xosc), set only by TrafficSignalStateAction. A signal nobody
//! has set has no state (esmini's `TrafficLight` starts with an empty state string).
//!
//! The scenario's traffic-signal controllers (`RoadNetwork/TrafficSignals`) are not run: esmini
//! 3.6.0 never reads that element (`ScenarioReader` has no parser for it), so their phases set no
//! state there, and its `ScenarioReader::parseOSCGlobalAction` drops a
//! TrafficSignalControllerAction ("not supported yet"). Each controller is a warning. Every change
//! of a signal's state is logged for the trace (`trace::SignalState`).

use crate::trace::SignalState;
use crate::Diagnostic;
use openscenario::Scenario;
use std::collections::{BTreeMap, BTreeSet};

/// Every signal's state.
#[derive(Debug, Clone, Default)]
pub(crate) struct Signals {
    /// Current state by signal name.
    states: BTreeMap<String, String>,
    /// OpenDRIVE signal ids of the road network (empty without one).
    known: BTreeSet<String>,
    /// Every change of a signal's state, in the order it happened.
    pub log: Vec<SignalState>,
}

impl Signals {
    /// No signal has a state yet; each controller of the RoadNetwork is a warning (not run).
    pub(crate) fn new(scenario: &Scenario, net: Option<&opendrive::RoadNetwork>, warnings: &mut Vec<Diagnostic>) -> Self {
        for c in &scenario.road_network.traffic_signal_controllers {
            warnings.push(Diagnostic::at(
                &c.origin,
                format!(
                    "traffic signal controller `{}` is not run, as esmini 3.6.0 does not read RoadNetwork/TrafficSignals: its phases set no signal state",
                    c.name
                ),
            ));
        }
        Signals {
            states: BTreeMap::new(),
            known: net.map(|n| n.roads.iter().flat_map(|r| r.signals.iter().map(|g| g.id.clone())).collect()).unwrap_or_default(),
            log: Vec::new(),
        }
    }

    /// Set one signal's state at time `t`.
    pub(crate) fn set_state(&mut self, t: f64, signal: &str, state: &str) {
        set(&mut self.states, &mut self.log, t, signal, state);
    }

    /// Whether signal `signal` is in state `state` (compared lamp by lamp, ignoring case and
    /// blanks: "On;off" equals "on; off").
    pub(crate) fn is_in(&self, signal: &str, state: &str) -> bool {
        self.states.get(signal).is_some_and(|s| same_state(s, state))
    }

    /// Whether `signal` is a signal id of the road network (always true without a network's
    /// signals to check against).
    pub(crate) fn is_known(&self, signal: &str) -> bool {
        self.known.is_empty() || self.known.contains(signal)
    }
}

fn set(states: &mut BTreeMap<String, String>, log: &mut Vec<SignalState>, t: f64, signal: &str, state: &str) {
    if states.get(signal).is_some_and(|s| s == state) {
        return;
    }
    states.insert(signal.to_string(), state.to_string());
    log.push(SignalState { time: t, signal: signal.to_string(), state: state.to_string() });
}

fn same_state(a: &str, b: &str) -> bool {
    let mut x = a.split(';').map(str::trim);
    let mut y = b.split(';').map(str::trim);
    loop {
        match (x.next(), y.next()) {
            (None, None) => return true,
            (Some(p), Some(q)) if p.eq_ignore_ascii_case(q) => {}
            _ => return false,
        }
    }
}

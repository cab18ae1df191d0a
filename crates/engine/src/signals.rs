//! Traffic signals at run time: each signal's current state (signals are named by their
//! OpenDRIVE signal id, as in the xosc) and the scenario's traffic-signal controllers
//! (`RoadNetwork/TrafficSignals`), which cycle through their phases and set the states their
//! phases list when a phase begins.
//!
//! Timing, as the standard describes it: a controller's first phase starts at time 0, or, with
//! a `reference`, `delay` seconds after its reference's first phase starts (a delay without a
//! reference counts from time 0); the phases then repeat for ever. A controller is "virtually"
//! running before its start, so at time 0 it is already in the phase that cycle position gives.
//! A TrafficSignalStateAction sets one signal until a controller's next phase sets it again; a
//! TrafficSignalControllerAction restarts a controller in the named phase. Every change of a
//! signal's state is logged for the trace (`trace::SignalState`).

use crate::trace::SignalState;
use crate::Diagnostic;
use openscenario::{Scenario, TrafficSignalController};
use std::collections::{BTreeMap, BTreeSet};

/// Two times closer than this are the same instant (engine times are `k * dt`).
const EPS: f64 = 1e-9;
/// Phase boundaries per controller step are bounded by the number of phases; a cycle shorter
/// than this is treated as not cycling (a hostile file could otherwise ask for millions of
/// phase changes per step).
const MIN_CYCLE: f64 = 1e-6;

/// One controller while the scenario runs.
#[derive(Debug, Clone)]
pub(crate) struct ControllerRt<'a> {
    pub model: &'a TrafficSignalController,
    /// Start time of each phase within a cycle; `starts[n]` is the cycle length.
    starts: Vec<f64>,
    /// Time at which (some repetition of) the first phase starts.
    origin: f64,
    /// The phase in force (None: no phases).
    pub phase: Option<usize>,
}

impl<'a> ControllerRt<'a> {
    fn new(model: &'a TrafficSignalController, origin: f64) -> Self {
        let mut starts = Vec::with_capacity(model.phases.len() + 1);
        let mut t = 0.0;
        starts.push(t);
        for p in &model.phases {
            t += if p.duration.is_finite() { p.duration.max(0.0) } else { 0.0 };
            starts.push(t);
        }
        ControllerRt { model, starts, origin, phase: None }
    }

    fn cycle(&self) -> f64 {
        self.starts.last().copied().unwrap_or(0.0)
    }

    /// The phase in force at time `t`.
    fn phase_at(&self, t: f64) -> Option<usize> {
        let n = self.model.phases.len();
        if n == 0 {
            return None;
        }
        let cycle = self.cycle();
        if cycle < MIN_CYCLE {
            return Some(0);
        }
        let mut pos = (t - self.origin).rem_euclid(cycle);
        if pos + EPS >= cycle {
            pos = 0.0;
        }
        // The last phase whose start is at or before `pos` (zero-length phases are passed over).
        (0..n).rev().find(|&i| self.starts[i] <= pos + EPS && self.starts[i + 1] > pos + EPS).or(Some(0))
    }
}

/// Every signal's state and every controller.
#[derive(Debug, Clone, Default)]
pub(crate) struct Signals<'a> {
    /// Current state by signal name.
    states: BTreeMap<String, String>,
    pub controllers: Vec<ControllerRt<'a>>,
    /// OpenDRIVE signal ids of the road network (empty without one).
    known: BTreeSet<String>,
    /// Every change of a signal's state, in the order it happened.
    pub log: Vec<SignalState>,
}

impl<'a> Signals<'a> {
    /// The scenario's controllers, each in the phase it is in at time 0 (whose states are set).
    pub(crate) fn new(scenario: &'a Scenario, net: Option<&opendrive::RoadNetwork>, warnings: &mut Vec<Diagnostic>) -> Self {
        let models = &scenario.road_network.traffic_signal_controllers;
        let origins: Vec<f64> = (0..models.len()).map(|i| origin_of(models, i, warnings)).collect();
        let mut s = Signals {
            states: BTreeMap::new(),
            controllers: models.iter().zip(origins).map(|(m, o)| ControllerRt::new(m, o)).collect(),
            known: net.map(|n| n.roads.iter().flat_map(|r| r.signals.iter().map(|g| g.id.clone())).collect()).unwrap_or_default(),
            log: Vec::new(),
        };
        for c in &s.controllers {
            if !c.model.phases.is_empty() && c.cycle() < MIN_CYCLE {
                warnings.push(Diagnostic::at(
                    &c.model.origin,
                    format!("traffic signal controller `{}`: its phases last no time; it stays in its first phase", c.model.name),
                ));
            }
        }
        s.advance(0.0);
        s
    }

    /// Move every controller to the phase in force at time `t`, setting the states of each phase
    /// that begins.
    pub(crate) fn advance(&mut self, t: f64) {
        for i in 0..self.controllers.len() {
            let now = self.controllers[i].phase_at(t);
            if now != self.controllers[i].phase {
                self.controllers[i].phase = now;
                self.apply_phase(i, t);
            }
        }
    }

    /// Set the states phase `controllers[i].phase` lists.
    fn apply_phase(&mut self, i: usize, t: f64) {
        let c = &self.controllers[i];
        let Some(phase) = c.phase.and_then(|p| c.model.phases.get(p)) else { return };
        for (signal, state) in &phase.states {
            set(&mut self.states, &mut self.log, t, signal, state);
        }
    }

    /// Set one signal's state at time `t`.
    pub(crate) fn set_state(&mut self, t: f64, signal: &str, state: &str) {
        set(&mut self.states, &mut self.log, t, signal, state);
    }

    /// Restart controller `name` in phase `phase` at time `t`; Err says what was not found.
    pub(crate) fn set_phase(&mut self, t: f64, name: &str, phase: &str) -> Result<(), String> {
        let i = self.controller(name).ok_or_else(|| format!("traffic signal controller `{name}` is not defined in the RoadNetwork"))?;
        let c = &mut self.controllers[i];
        let j = c.model.phases.iter().position(|p| p.name == phase).ok_or_else(|| format!("traffic signal controller `{name}` has no phase `{phase}`"))?;
        c.origin = t - c.starts[j];
        c.phase = Some(j);
        self.apply_phase(i, t);
        Ok(())
    }

    /// Index of the controller named `name`.
    pub(crate) fn controller(&self, name: &str) -> Option<usize> {
        self.controllers.iter().position(|c| c.model.name == name)
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

/// When controller `i`'s first phase starts: its delay after its reference's start (following
/// references; an unknown or circular reference counts from time 0, with a warning).
fn origin_of(models: &[TrafficSignalController], i: usize, warnings: &mut Vec<Diagnostic>) -> f64 {
    let mut origin = 0.0;
    let mut cur = i;
    let mut seen = vec![false; models.len()];
    loop {
        let c = &models[cur];
        seen[cur] = true;
        origin += c.delay.filter(|d| d.is_finite()).unwrap_or(0.0);
        let Some(r) = c.reference.as_deref().filter(|r| !r.is_empty()) else { return origin };
        match models.iter().position(|m| m.name == r) {
            Some(next) if !seen[next] => cur = next,
            Some(_) => {
                warnings.push(Diagnostic::at(
                    &models[i].origin,
                    format!("traffic signal controller `{}`: its references go round in a circle; only the delays up to `{r}` count", models[i].name),
                ));
                return origin;
            }
            None => {
                if cur == i {
                    warnings.push(Diagnostic::at(
                        &c.origin,
                        format!("traffic signal controller `{}`: reference `{r}` is not a controller; its delay counts from time 0", c.name),
                    ));
                }
                return origin;
            }
        }
    }
}

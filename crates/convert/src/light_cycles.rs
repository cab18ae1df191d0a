//! A run's traffic-signal states become the cycle of the CommonRoad light made of that signal.
//!
//! CommonRoad 2020a knows a light only as a repeating cycle of colours. A run gives each signal
//! a history instead (its TrafficSignalStateActions: the engine, as esmini 3.6.0, runs no
//! RoadNetwork controller), so the cycle written is that history from time 0 to the end of the
//! scenario: it is exact over the scenario's time span (CommonRoad would repeat it afterwards).
//! A light whose signal no action sets keeps the map's default cycle, unless a RoadNetwork
//! controller's phases name it (`declared_cycles`).

use std::collections::BTreeMap;
use std::num::NonZeroU64;

use commonroad::{CycleElement, LaneletNetwork, TrafficLightColor, TrafficLightId};
use engine::SignalState;

/// The CommonRoad colour of an OpenSCENARIO signal state. esmini's lamp form lists the lamps
/// top to bottom, red;yellow;green (`"off;off;on"` is green); colour words are read too.
/// `None`: the state has no CommonRoad colour (e.g. a flashing lamp).
pub(crate) fn colour_of(state: &str) -> Option<TrafficLightColor> {
    let lamps: Vec<String> = state.split(';').map(|l| l.trim().to_ascii_lowercase()).collect();
    let on = |l: &String| match l.as_str() {
        "on" => Some(true),
        "off" => Some(false),
        _ => None,
    };
    if let [r, y, g] = lamps.as_slice() {
        return match (on(r)?, on(y)?, on(g)?) {
            (true, false, false) => Some(TrafficLightColor::Red),
            (true, true, false) => Some(TrafficLightColor::RedYellow),
            (false, false, true) => Some(TrafficLightColor::Green),
            (false, true, false) => Some(TrafficLightColor::Yellow),
            (false, false, false) => Some(TrafficLightColor::Inactive),
            _ => None,
        };
    }
    let [word] = lamps.as_slice() else { return None };
    match word.replace(['_', '-', ' '], "").as_str() {
        "red" | "stop" => Some(TrafficLightColor::Red),
        "redyellow" | "redamber" => Some(TrafficLightColor::RedYellow),
        "green" | "go" => Some(TrafficLightColor::Green),
        "yellow" | "amber" => Some(TrafficLightColor::Yellow),
        "off" | "inactive" | "dark" => Some(TrafficLightColor::Inactive),
        _ => None,
    }
}

/// Replaces the cycle of every light whose signal the run set. `end_time` is the scenario's
/// last time, `dt` the CommonRoad time step. Returns the warnings (states without a colour).
pub(crate) fn apply_signal_states(
    network: &mut LaneletNetwork,
    light_of_signal: &BTreeMap<String, TrafficLightId>,
    states: &[SignalState],
    end_time: f64,
    dt: f64,
) -> Vec<String> {
    let mut warnings = Vec::new();
    if !(dt > 0.0 && end_time.is_finite()) {
        return warnings;
    }
    // Time steps the scenario has: 0..=last.
    let last = (end_time.max(0.0) / dt).round() as u64;
    let mut history: BTreeMap<&str, Vec<(u64, TrafficLightColor)>> = BTreeMap::new();
    for s in states {
        let Some(_) = light_of_signal.get(&s.signal) else { continue };
        let colour = colour_of(&s.state).unwrap_or_else(|| {
            warnings.push(format!("signal `{}` state {:?} at {:.2} s has no CommonRoad light colour; written as inactive", s.signal, s.state, s.time));
            TrafficLightColor::Inactive
        });
        let step = (s.time.max(0.0) / dt).round() as u64;
        history.entry(s.signal.as_str()).or_default().push((step.min(last), colour));
    }
    for (signal, changes) in history {
        let Some(id) = light_of_signal.get(signal) else { continue };
        let Some(light) = network.traffic_lights.iter_mut().find(|l| l.id == *id) else { continue };
        if let Some(cycle) = cycle_of(&changes, last) {
            light.cycle = cycle;
            light.time_offset = 0;
        }
    }
    warnings
}

/// Colour segments from `changes` (step, colour), in time order, up to step `last`; before the
/// first change the light is inactive. Several changes in one step: the last one holds.
fn cycle_of(changes: &[(u64, TrafficLightColor)], last: u64) -> Option<Vec<CycleElement>> {
    let mut points: Vec<(u64, TrafficLightColor)> = Vec::new();
    if changes.first().is_some_and(|(k, _)| *k > 0) {
        points.push((0, TrafficLightColor::Inactive));
    }
    for &(k, c) in changes {
        match points.last_mut() {
            Some(p) if p.0 == k => p.1 = c,
            _ => points.push((k, c)),
        }
    }
    let mut cycle: Vec<CycleElement> = Vec::new();
    for (i, &(k, colour)) in points.iter().enumerate() {
        // a segment lasts to the next change, the last one to the end of the scenario
        let until = points.get(i + 1).map_or(last + 1, |p| p.0);
        let Some(duration) = NonZeroU64::new(until.saturating_sub(k)) else { continue };
        match cycle.last_mut() {
            Some(prev) if prev.color == colour => {
                prev.duration = prev.duration.saturating_add(duration.get());
            }
            _ => cycle.push(CycleElement { duration, color: colour }),
        }
    }
    (!cycle.is_empty()).then_some(cycle)
}

#[cfg(test)]
mod tests {
    use super::*;
    use TrafficLightColor::*;

    #[test]
    fn lamp_states_and_words() {
        assert_eq!(colour_of("on;off;off"), Some(Red));
        assert_eq!(colour_of("on;on;off"), Some(RedYellow));
        assert_eq!(colour_of(" off ; off ; ON "), Some(Green));
        assert_eq!(colour_of("off;on;off"), Some(Yellow));
        assert_eq!(colour_of("off;off;off"), Some(Inactive));
        assert_eq!(colour_of("green"), Some(Green));
        assert_eq!(colour_of("red_yellow"), Some(RedYellow));
        assert_eq!(colour_of("on;off"), None, "a pedestrian light has no vehicle colour");
        assert_eq!(colour_of("flashing;off;off"), None);
        assert_eq!(colour_of("on;off;on"), None);
    }

    fn d(n: u64) -> NonZeroU64 {
        NonZeroU64::new(n).unwrap_or(NonZeroU64::MIN)
    }

    #[test]
    fn history_becomes_segments_to_the_end() {
        // green from 0, yellow at step 35, red at 65, green again at 150; 301 steps in all
        let c = cycle_of(&[(0, Green), (35, Yellow), (65, Red), (150, Green)], 300).unwrap_or_default();
        let want = [(35, Green), (30, Yellow), (85, Red), (151, Green)];
        assert_eq!(c.len(), want.len());
        for (e, (n, col)) in c.iter().zip(want) {
            assert_eq!((e.duration, e.color), (d(n), col));
        }
        assert_eq!(c.iter().map(|e| e.duration.get()).sum::<u64>(), 301);
    }

    #[test]
    fn late_first_state_same_step_changes_and_repeats() {
        // set at step 10 (inactive before); two changes in step 20, the last holds; a repeat merges
        let c = cycle_of(&[(10, Red), (20, Green), (20, Yellow), (30, Yellow)], 39).unwrap_or_default();
        let got: Vec<(u64, TrafficLightColor)> = c.iter().map(|e| (e.duration.get(), e.color)).collect();
        assert_eq!(got, vec![(10, Inactive), (10, Red), (20, Yellow)]);
    }
}

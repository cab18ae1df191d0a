//! The cycles the scenario's traffic-signal controllers (`RoadNetwork/TrafficSignals`) declare,
//! written as the CommonRoad cycles of the lights their phases name.
//!
//! The run does not cycle them: esmini 3.6.0 never reads that element, so the engine (as esmini)
//! sets a signal's state only by TrafficSignalStateAction and no condition of the run sees a
//! phase. CommonRoad's light cycle, however, is exactly what a controller declares (colours and
//! durations, a time offset), so a light whose signal the run never set gets its controller's
//! cycle rather than the map's default: the author's declared cycle is kept in the output. A
//! signal the run did set keeps the run's history (what esmini shows); the declared cycle it
//! shadows is a warning. Every controller written this way is a warning too.
//!
//! Timing, as the standard describes it: a controller's first phase starts `delay` seconds after
//! its `reference`'s first phase (following references; a delay without a reference counts from
//! time 0) and the phases repeat for ever. A phase sets the states it lists when it begins; a
//! signal a phase does not name keeps the state an earlier phase (cyclically) gave it.

use std::collections::{BTreeMap, BTreeSet};
use std::num::NonZeroU64;

use commonroad::{CycleElement, LaneletNetwork, TrafficLightColor, TrafficLightId};
use openscenario::TrafficSignalController;

use crate::light_cycles::colour_of;

/// One signal's cycle as a controller declares it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct DeclaredCycle {
    /// The controller's name.
    pub controller: String,
    pub cycle: Vec<CycleElement>,
    /// CommonRoad's offset in steps: the colour at step t is the cycle's at (t − offset) mod total.
    pub time_offset: u64,
}

/// The declared cycle of every signal a controller's phases name, in CommonRoad steps of `dt`
/// seconds. A signal named by several controllers takes the first one's (a warning); a
/// controller whose phases last less than one step declares nothing (a warning).
pub(crate) fn declared_cycles(controllers: &[TrafficSignalController], dt: f64, warnings: &mut Vec<String>) -> BTreeMap<String, DeclaredCycle> {
    let mut out: BTreeMap<String, DeclaredCycle> = BTreeMap::new();
    if !(dt > 0.0 && dt.is_finite()) {
        return out;
    }
    for (i, c) in controllers.iter().enumerate() {
        // phase i spans steps bounds[i]..bounds[i + 1]; rounding the running sum keeps the total exact
        let mut bounds = vec![0u64];
        let mut t = 0.0;
        for p in &c.phases {
            t += if p.duration.is_finite() { p.duration.max(0.0) } else { 0.0 };
            bounds.push((t / dt).round() as u64);
        }
        let total = bounds.last().copied().unwrap_or(0);
        // A phase's TrafficSignalGroupState (1.2) sets a whole group at once; CommonRoad's lights
        // know no groups, and esmini 3.6.0 reads none of this, so it is left out, said once a phase.
        for p in c.phases.iter().filter(|p| p.group_state.is_some()) {
            warnings.push(format!(
                "TrafficSignalController `{}` ({}): phase `{}`'s TrafficSignalGroupState is not written (a CommonRoad light has no group state); only its TrafficSignalStates make the light cycle",
                c.name, c.origin, p.name
            ));
        }
        let named: BTreeSet<&str> = c.phases.iter().flat_map(|p| p.states.iter().map(|(s, _)| s.as_str())).collect();
        if named.is_empty() {
            continue;
        }
        if total == 0 {
            warnings.push(format!(
                "TrafficSignalController `{}` ({}): its phases last less than one time step; no light cycle is written from it",
                c.name, c.origin
            ));
            continue;
        }
        let start = (origin_of(controllers, i, warnings) / dt).round() as i128;
        let time_offset = start.rem_euclid(total as i128) as u64;
        for signal in named {
            if let Some(first) = out.get(signal) {
                warnings.push(format!(
                    "TrafficSignalController `{}` ({}): signal `{signal}` is also named by `{}`, whose cycle is written",
                    c.name, c.origin, first.controller
                ));
                continue;
            }
            let cycle = cycle_of_signal(c, signal, &bounds, warnings);
            if !cycle.is_empty() {
                out.insert(signal.to_string(), DeclaredCycle { controller: c.name.clone(), cycle, time_offset });
            }
        }
    }
    out
}

/// The colour segments of `signal` over one cycle of `c` (phase boundaries `bounds`, in steps).
fn cycle_of_signal(c: &TrafficSignalController, signal: &str, bounds: &[u64], warnings: &mut Vec<String>) -> Vec<CycleElement> {
    let state_in = |p: &openscenario::Phase| p.states.iter().rev().find(|(s, _)| s == signal).map(|(_, st)| st.clone());
    // a phase not naming the signal keeps what the last phase naming it set, round the cycle
    let mut held = c.phases.iter().rev().find_map(state_in);
    let mut cycle: Vec<CycleElement> = Vec::new();
    for (i, p) in c.phases.iter().enumerate() {
        if let Some(s) = state_in(p) {
            held = Some(s);
        }
        let steps = bounds[i + 1].saturating_sub(bounds[i]);
        let (Some(duration), Some(state)) = (NonZeroU64::new(steps), held.as_deref()) else { continue };
        let colour = colour_of(state).unwrap_or_else(|| {
            warnings.push(format!(
                "TrafficSignalController `{}` phase `{}`: signal `{signal}` state {state:?} has no CommonRoad light colour; written as inactive",
                c.name, p.name
            ));
            TrafficLightColor::Inactive
        });
        match cycle.last_mut() {
            Some(prev) if prev.color == colour => prev.duration = prev.duration.saturating_add(duration.get()),
            _ => cycle.push(CycleElement { duration, color: colour }),
        }
    }
    cycle
}

/// When controller `i`'s first phase starts (seconds): its delay after its reference's start,
/// following references; an unknown or circular reference ends the chain, with a warning.
fn origin_of(controllers: &[TrafficSignalController], i: usize, warnings: &mut Vec<String>) -> f64 {
    let mut origin = 0.0;
    let mut seen = vec![false; controllers.len()];
    let mut cur = i;
    loop {
        let c = &controllers[cur];
        seen[cur] = true;
        origin += c.delay.filter(|d| d.is_finite()).unwrap_or(0.0);
        let Some(r) = c.reference.as_deref().filter(|r| !r.is_empty()) else { return origin };
        match controllers.iter().position(|m| m.name == r) {
            Some(next) if !seen[next] => cur = next,
            found => {
                let why = if found.is_some() { "its references go round in a circle" } else { "it is not a controller" };
                warnings.push(format!(
                    "TrafficSignalController `{}` ({}): reference `{r}`: {why}; the cycle's offset counts only the delays up to it",
                    controllers[i].name, controllers[i].origin
                ));
                return origin;
            }
        }
    }
}

/// Writes the declared cycle into the light of every signal the run did not set (`set_by_run`).
/// Returns the warnings: one per controller written, one per declared cycle the run's history
/// shadows.
pub(crate) fn apply_declared_cycles(
    network: &mut LaneletNetwork,
    light_of_signal: &BTreeMap<String, TrafficLightId>,
    declared: &BTreeMap<String, DeclaredCycle>,
    set_by_run: &BTreeSet<&str>,
    controllers: &[TrafficSignalController],
) -> Vec<String> {
    let mut warnings = Vec::new();
    let mut written: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for (signal, d) in declared {
        let Some(id) = light_of_signal.get(signal) else { continue };
        let Some(light) = network.traffic_lights.iter_mut().find(|l| l.id == *id) else { continue };
        if set_by_run.contains(signal.as_str()) {
            warnings.push(format!(
                "TrafficSignalController `{}`: signal `{signal}` was set by a TrafficSignalStateAction during the run, so its CommonRoad light cycle is the run's history, not the controller's declared cycle",
                d.controller
            ));
            continue;
        }
        light.cycle = d.cycle.clone();
        light.time_offset = d.time_offset;
        light.active = Some(true);
        written.entry(d.controller.as_str()).or_default().push(signal);
    }
    for c in controllers {
        let Some(signals) = written.get(c.name.as_str()) else { continue };
        warnings.push(format!(
            "TrafficSignalController `{}` ({}): esmini 3.6.0 does not run it, so no condition of the run saw its phases; its phases are written as the CommonRoad light cycle of signals {}",
            c.name,
            c.origin,
            signals.join(", ")
        ));
    }
    warnings
}

#[cfg(test)]
mod tests {
    use super::*;
    use openscenario::{Location, Phase};
    use std::path::Path;
    use TrafficLightColor::*;

    fn phase(name: &str, duration: f64, states: &[(&str, &str)]) -> Phase {
        Phase { name: name.into(), duration, states: states.iter().map(|(a, b)| (a.to_string(), b.to_string())).collect(), group_state: None }
    }

    fn controller(name: &str, delay: Option<f64>, reference: Option<&str>, phases: Vec<Phase>) -> TrafficSignalController {
        TrafficSignalController { name: name.into(), delay, reference: reference.map(str::to_string), phases, origin: Location::file_only(Path::new("t.xosc")) }
    }

    fn steps(d: &DeclaredCycle) -> Vec<(u64, TrafficLightColor)> {
        d.cycle.iter().map(|e| (e.duration.get(), e.color)).collect()
    }

    #[test]
    fn phases_give_each_signal_its_colours_and_references_their_offset() {
        let a = controller(
            "A",
            Some(1.0),
            None,
            vec![
                phase("go", 3.0, &[("1", "off;off;on"), ("2", "on;off;off")]),
                phase("amber", 0.5, &[("1", "off;on;off")]),
                phase("stop", 4.0, &[("1", "on;off;off"), ("2", "off;off;on")]),
                phase("all_red", 0.5, &[("2", "on;off;off")]),
            ],
        );
        let b = controller("B", Some(2.0), Some("A"), vec![phase("p", 1.0, &[("3", "red")]), phase("q", 1.0, &[("3", "green")])]);
        let mut w = Vec::new();
        let d = declared_cycles(&[a, b], 0.1, &mut w);
        assert!(w.is_empty(), "{w:?}");
        // signal 1 is red through the all-red phase, which does not name it
        assert_eq!(steps(&d["1"]), vec![(30, Green), (5, Yellow), (45, Red)]);
        // signal 2 keeps red from the last phase into the first, and the total is the cycle's 80 steps
        assert_eq!(steps(&d["2"]), vec![(35, Red), (40, Green), (5, Red)]);
        assert_eq!((d["1"].time_offset, d["2"].time_offset), (10, 10));
        // B starts 2 s after A's start at 1 s: 30 steps, modulo its 20-step cycle
        assert_eq!(steps(&d["3"]), vec![(10, Red), (10, Green)]);
        assert_eq!((d["3"].controller.as_str(), d["3"].time_offset), ("B", 10));
    }

    #[test]
    fn doubles_circles_and_timeless_controllers_are_warnings() {
        let a = controller("A", Some(0.5), Some("B"), vec![phase("p", 2.0, &[("1", "green")])]);
        let b = controller("B", Some(0.2), Some("A"), vec![phase("p", 1.0, &[("1", "red"), ("2", "flashing")])]);
        let c = controller("C", None, None, vec![phase("p", 0.01, &[("4", "red")])]);
        let mut w = Vec::new();
        let d = declared_cycles(&[a, b, c], 0.1, &mut w);
        assert_eq!(steps(&d["1"]), vec![(20, Green)], "the first controller naming a signal wins");
        assert_eq!(d["1"].time_offset, 7, "0.5 s + 0.2 s, the circle cut at A");
        assert_eq!(steps(&d["2"]), vec![(10, Inactive)]);
        assert!(!d.contains_key("4"));
        for needle in ["go round in a circle", "also named by `A`", "no CommonRoad light colour", "less than one time step"] {
            assert!(w.iter().any(|m| m.contains(needle)), "{needle}: {w:?}");
        }
        assert!(!w.iter().any(|m| m.contains("TrafficSignalGroupState")), "{w:?}");
    }

    #[test]
    fn a_group_state_is_left_out_with_a_warning() {
        let mut grouped = phase("all", 1.0, &[("1", "red")]);
        grouped.group_state = Some("red;off".into());
        let c = controller("G", None, None, vec![grouped, phase("go", 1.0, &[("1", "green")])]);
        let mut w = Vec::new();
        let d = declared_cycles(&[c], 0.1, &mut w);
        assert_eq!(steps(&d["1"]), vec![(10, Red), (10, Green)]);
        assert_eq!(w.len(), 1, "{w:?}");
        for needle in ["`G`", "phase `all`", "TrafficSignalGroupState is not written"] {
            assert!(w.iter().any(|m| m.contains(needle)), "{needle}: {w:?}");
        }
    }
}

//! The storyboard events of a run as marks for a picture: each time an OpenSCENARIO Event
//! starts (the event log's `start` into `running`), named by the Event.

use std::collections::BTreeSet;

use engine::StoryboardEvent;
use openscenario::Scenario;

/// (time, event name) of every Event start, in the log's order; times before 0 (a ghost's
/// head start) are left out, as the CommonRoad scenario starts at 0.
pub fn event_marks(scenario: &Scenario, log: &[StoryboardEvent]) -> Vec<(f64, String)> {
    let names: BTreeSet<&str> = scenario.storyboard.events().map(|e| e.name.as_str()).collect();
    log.iter()
        .filter(|e| e.transition == "start" && e.to == "running" && e.time >= 0.0)
        .filter(|e| names.contains(e.element.as_str()))
        .map(|e| (e.time, e.element.clone()))
        .collect()
}

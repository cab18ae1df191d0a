//! esmini's object ids: the number a message's `objectId` names and the default port adds to
//! the base port — an object's place in esmini's object order (`osi::esmini_objects`: the
//! ScenarioObjects in document order from 0, each vehicle's inline trailer right after it,
//! named like its tow vehicle with a `+`; ghosts come after all).

use openscenario::Scenario;

/// Each object's name and esmini id, in id order.
pub fn object_ids(scenario: &Scenario) -> Vec<(String, u32)> {
    osi::esmini_objects(scenario).into_iter().enumerate().map(|(i, (name, _))| (name, i as u32)).collect()
}

/// The esmini id of the object named `name`.
pub fn object_id(ids: &[(String, u32)], name: &str) -> Option<u32> {
    ids.iter().find(|(n, _)| n == name).map(|(_, id)| *id)
}

//! esmini's object ids: the number a message's `objectId` names and the default port adds to
//! the base port. esmini numbers objects as it adds them while reading the scenario
//! (`Entities::addObject`): the ScenarioObjects in document order from 0, each vehicle's inline
//! trailer (and that trailer's own, and so on) right after it, named like its tow vehicle with a
//! `+`. A TrailerRef names an object added before and takes no number; ghosts come after all.

use openscenario::{EntityObject, Scenario, Trailer};

/// Longest chain of inline trailers followed (a hostile file may nest them deeply).
const MAX_TRAILERS: usize = 100;

/// Each object's name and esmini id, in id order.
pub fn object_ids(scenario: &Scenario) -> Vec<(String, u32)> {
    let mut ids = Vec::new();
    let mut next = 0u32;
    for entity in &scenario.entities {
        ids.push((entity.name.clone(), next));
        next += 1;
        let (mut model, mut name) = (entity, entity.name.clone());
        for _ in 0..MAX_TRAILERS {
            let EntityObject::Vehicle(v) = &model.object else { break };
            let Some(Trailer::Entity(inner)) = &v.trailer else { break };
            name.push('+');
            ids.push((name.clone(), next));
            next += 1;
            model = inner;
        }
    }
    ids
}

/// The esmini id of the object named `name`.
pub fn object_id(ids: &[(String, u32)], name: &str) -> Option<u32> {
    ids.iter().find(|(n, _)| n == name).map(|(_, id)| *id)
}

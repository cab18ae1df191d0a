//! The scenario's objects in esmini's order (`Entities::addObject`): the ScenarioObjects in
//! document order, each vehicle's inline trailer (and its trailer, and so on) right after it,
//! named like its tow vehicle with a `+`. A TrailerRef names an object added before. The
//! position in this list is esmini's object id; plus the first entity id of `GlobalIds`, the
//! object's OSI id.

use openscenario::{Entity, EntityObject, Scenario, Trailer};

/// Longest chain of inline trailers followed (a hostile file may nest them deeply).
const MAX_TRAILERS: usize = 100;

/// Each object's name and model, in esmini's order.
pub fn esmini_objects(scenario: &Scenario) -> Vec<(String, &Entity)> {
    let mut out = Vec::new();
    for entity in &scenario.entities {
        out.push((entity.name.clone(), entity));
        let (mut model, mut name) = (entity, entity.name.clone());
        for _ in 0..MAX_TRAILERS {
            let EntityObject::Vehicle(v) = &model.object else { break };
            let Some(Trailer::Entity(inner)) = &v.trailer else { break };
            name.push('+');
            out.push((name.clone(), inner.as_ref()));
            model = inner;
        }
    }
    out
}

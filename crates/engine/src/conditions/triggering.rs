//! Which entities made a trigger true: the triggering entities for which the entity
//! conditions of its true condition groups held (for `selectTriggeringEntities`).

use super::TriggerRt;

impl TriggerRt<'_> {
    /// The entities that made the trigger true at its last evaluation, in order of first
    /// mention, without repeats; empty when no true group holds an entity condition.
    pub(crate) fn triggering_entities(&self) -> Vec<usize> {
        let mut out = Vec::new();
        for g in &self.groups {
            if g.is_empty() || !g.iter().all(|c| c.value) {
                continue;
            }
            for c in g {
                for &e in &c.fired_by {
                    if !out.contains(&e) {
                        out.push(e);
                    }
                }
            }
        }
        out
    }
}

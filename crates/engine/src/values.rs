//! Parameters and variables as the storyboard sees them at run time (set and modified by
//! global actions, read by conditions). Ordered by name for deterministic output.

use openscenario::{ModifyKind, ModifyRule, ParameterDeclaration};
use std::collections::BTreeMap;

#[derive(Debug, Clone, Default)]
pub(crate) struct Values {
    map: BTreeMap<String, String>,
}

impl Values {
    pub(crate) fn from_declarations(decls: &[ParameterDeclaration]) -> Values {
        Values { map: decls.iter().map(|d| (d.name.clone(), d.value.clone())).collect() }
    }

    pub(crate) fn get(&self, name: &str) -> Option<&str> {
        self.map.get(name.trim_start_matches('$')).map(String::as_str)
    }

    /// Set a value; false when the name is not declared (the value is still recorded).
    pub(crate) fn set(&mut self, name: &str, value: &str) -> bool {
        let key = name.trim_start_matches('$');
        let known = self.map.contains_key(key);
        self.map.insert(key.to_string(), value.to_string());
        known
    }

    /// Apply a modify rule to a numeric value; false when the value is missing or not a number.
    pub(crate) fn modify(&mut self, name: &str, rule: &ModifyRule) -> bool {
        let key = name.trim_start_matches('$');
        let Some(v) = self.map.get(key).and_then(|v| v.trim().parse::<f64>().ok()) else { return false };
        let n = match rule.kind {
            ModifyKind::Add => v + rule.value,
            ModifyKind::Multiply => v * rule.value,
        };
        let text = if n.fract() == 0.0 && n.abs() < 1e15 { format!("{}", n as i64) } else { format!("{n}") };
        self.map.insert(key.to_string(), text);
        true
    }
}

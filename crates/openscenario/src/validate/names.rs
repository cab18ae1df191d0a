//! Names that must be unique where they stand. The standard: "Element names at each level shall
//! be unique at that level" — no two children of one element may carry the same `name` (two
//! events of one maneuver, two entries of one catalog, two declarations of one parameter block),
//! while the same name may be used again under another parent. esmini reads such files (the
//! later declaration of a parameter or entity wins, a reference takes the first element it
//! finds), and so many that esmini ships and runs have them (its demos repeat maneuver group and
//! event names) that a repeated name is a warning, at its second use: a scenario esmini runs as
//! its author meant is not refused for it. Repeated parameter, variable and entity names are
//! the reader's to say (with which one wins).

use super::{Severity, Walker};
use crate::xml::Elem;

impl Walker {
    /// The children of `el` that repeat a sibling's name (resolved when it is a `$parameter` of
    /// the scope in force).
    pub(super) fn unique_names(&mut self, el: &Elem) {
        let mut seen: Vec<(String, &Elem)> = Vec::new();
        for child in el.children_unmarked() {
            if matches!(child.name.as_str(), "ParameterDeclaration" | "VariableDeclaration" | "ScenarioObject") {
                continue;
            }
            let Some(raw) = child.attrs.iter().find(|a| a.name == "name") else { continue };
            let name = if raw.value.starts_with('$') { self.evaluate(&raw.value).unwrap_or_else(|_| raw.value.clone()) } else { raw.value.clone() };
            match seen.iter().find(|(n, _)| *n == name) {
                Some((_, first)) => {
                    let what = if first.name == child.name { format!("another <{}>", child.name) } else { format!("a <{}>", first.name) };
                    self.push(
                        Severity::Warning,
                        raw.pos,
                        format!(
                            "<{}> is named '{name}' like {what} at line {} in the same <{}>: the standard requires the names of one parent's \
                             elements to be unique (esmini reads it; a reference by this name finds the first)",
                            child.name, first.pos.line, el.name
                        ),
                    );
                }
                None => seen.push((name, child)),
            }
        }
    }
}

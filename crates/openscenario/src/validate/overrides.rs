//! Overrides of global parameters (`--param NAME=VALUE`, a distribution's values) whose value
//! does not fit the type the scenario declares for the parameter. The schema pass reports them
//! among every other finding; a caller that has to say *why* a file cannot be used (the
//! override, not the file) asks this on its own, with the same type rules.

use super::values::{fits_declared_type, parameter_type_name, primitive_of_parameter_type};
use crate::error::Location;
use crate::xml;
use std::path::Path;

/// An override whose value is not of its parameter's declared type.
#[derive(Debug, Clone, PartialEq)]
pub struct BadOverride {
    pub name: String,
    pub value: String,
    /// The declared type as the schema's ParameterType literal says it (`double`, `integer`, …).
    pub declared: &'static str,
    /// The parameter's declaration.
    pub location: Location,
    /// Why the value does not fit (`'abc' is not a valid double`).
    pub why: String,
}

/// The overrides of `path`'s global parameters that do not fit their declared types, in the
/// order given. A file that cannot be read, and overrides of parameters it does not declare,
/// give none (they are other problems, reported as such).
pub fn bad_overrides(path: &Path, overrides: &[(String, String)]) -> Vec<BadOverride> {
    if overrides.is_empty() {
        return Vec::new();
    }
    let Ok(doc) = xml::read_file(path) else { return Vec::new() };
    let Some(block) = doc.root.child("ParameterDeclarations") else { return Vec::new() };
    let declarations: Vec<&xml::Elem> = block.children_named("ParameterDeclaration").collect();
    let mut out = Vec::new();
    for (name, value) in overrides {
        // a name declared twice: the later declaration is the one that counts
        let declared = declarations.iter().rev().find(|d| d.attr("name").is_some_and(|a| a.value.trim().trim_start_matches('$') == name));
        let Some(d) = declared else { continue };
        let Some(primitive) = d.attr("parameterType").and_then(|a| primitive_of_parameter_type(a.value.trim())) else { continue };
        if let Err(why) = fits_declared_type(primitive, value) {
            out.push(BadOverride {
                name: name.clone(),
                value: value.clone(),
                declared: parameter_type_name(primitive),
                location: Location { file: doc.file.clone(), line: d.pos.line, col: d.pos.col },
                why,
            });
        }
    }
    out
}

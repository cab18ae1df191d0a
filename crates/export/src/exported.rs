//! One scenario exported: its OpenSCENARIO text and its map (through a map cache a batch
//! shares), the warnings of both, and why it could not be exported when it could not.

use std::sync::Arc;

use crate::map_file::{MapCache, MapFile};
use crate::options::ExportOptions;
use crate::scenario::{document, Facts};
use crate::source::Source;

/// One exported scenario: the OpenSCENARIO text, its map (`None`: the network has no lanelet;
/// the map's own warnings are in [`MapFile::warnings`]), what could not be said exactly, and
/// what it holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Exported {
    pub xosc: String,
    pub map: Option<Arc<MapFile>>,
    pub warnings: Vec<String>,
    pub facts: Facts,
}

/// Why a scenario could not be exported.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct ExportError(pub String);

/// Exports one scenario. The scenario names its map as `map_prefix` + the map's file name (the
/// relative path from where the `.xosc` is written to where the map is, e.g. `"../"`).
pub fn export(source: &Source, map_prefix: &str, options: &ExportOptions) -> Result<Exported, ExportError> {
    export_with(source, map_prefix, options, &MapCache::new())
}

/// Like [`export`], converting the map through `cache` (a batch shares one).
pub fn export_with(source: &Source, map_prefix: &str, options: &ExportOptions, cache: &MapCache) -> Result<Exported, ExportError> {
    let map = cache.get(&source.scenario).map_err(ExportError)?;
    let mut warnings = source.warnings.clone();
    if map.is_none() {
        warnings.push("the lanelet network has no lanelet: no map is written and the scenario names none".to_string());
    }
    let logic_file = map.as_ref().map(|m| format!("{map_prefix}{}", m.file_name));
    let doc = document(&source.scenario, &source.problems, logic_file.as_deref(), options).map_err(ExportError)?;
    warnings.extend(doc.warnings);
    Ok(Exported { xosc: doc.xosc, map, warnings, facts: doc.facts })
}

//! Reading a CommonRoad scenario: 2018b and 2020a XML (`commonroad::xml`), or the 2024
//! protobuf files named by the scenario file `NAME-SC.pb` (`commonroad::protobuf::read`).

use std::path::Path;

use commonroad::{PlanningProblemSet, Scenario};

/// A CommonRoad scenario as read, with the reader's warnings.
#[derive(Debug, Clone, PartialEq)]
pub struct Source {
    pub scenario: Scenario,
    pub problems: PlanningProblemSet,
    pub warnings: Vec<String>,
}

/// Whether `path` is a file `osc2cr export` reads: `.xml`, or a 2024 scenario file `*-SC.pb`.
pub fn is_input(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("xml")) || commonroad::protobuf::read::is_scenario_file(path)
}

/// Reads a scenario file. Errors name the file (and line and column for XML).
pub fn read_source(path: &Path) -> Result<Source, String> {
    if commonroad::protobuf::read::is_scenario_file(path) {
        let r = commonroad::protobuf::read::read_files(path).map_err(|e| e.to_string())?;
        return Ok(Source { scenario: r.scenario, problems: r.problems, warnings: r.warnings });
    }
    let r = commonroad::xml::read_scenario_file(path).map_err(|e| e.to_string())?;
    Ok(Source { scenario: r.scenario, problems: r.problems, warnings: r.warnings.iter().map(ToString::to_string).collect() })
}

/// The scenario's name: the file name without `.xml` (2024: without `-SC.pb`).
pub fn scenario_name(path: &Path) -> String {
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    if let Some(stem) = name.strip_suffix("-SC.pb") {
        return stem.to_string();
    }
    path.file_stem().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "scenario".to_string())
}

//! The CommonRoad 2024 reader: the map, scenario and dynamic files back into the 2020a model
//! ([`Scenario`] + [`PlanningProblemSet`]), the inverse of [`super::write`]. What the model
//! cannot hold is a warning naming it and is left out (set-based predictions, phantom obstacles,
//! areas, truck shapes as their boxes); uncertain values (intervals, position shapes) are read
//! as their midpoints and centres, as the XML reader reads 2018b files.
//!
//! [`read_files`] finds the three files from the scenario file's name, as commonroad-io's
//! writer and `osc2cr convert --format 2024` name them (`NAME-SC.pb`, `NAME.pb`, and
//! `<map id>.pb` beside them or in a folder above).

mod dynamic;
mod map;
mod scenario;
mod values;

use std::path::{Path, PathBuf};

use prost::Message;

use super::messages::{commonroad_dynamic as dy, commonroad_map as mp, commonroad_scenario as sc};
use crate::planning::PlanningProblemSet;
use crate::scenario::Scenario;

/// Largest file the reader loads (as the XML reader).
pub const MAX_FILE_BYTES: u64 = crate::xml::MAX_FILE_BYTES;

/// How many folders above the scenario file are searched for its map.
const MAP_SEARCH_DEPTH: usize = 8;

/// Why the three files could not be read into the model.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    #[error("cannot read {path}: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: {bytes} bytes is larger than the {MAX_FILE_BYTES} bytes the reader accepts")]
    TooLarge { path: PathBuf, bytes: u64 },
    #[error("{path}: not a CommonRoad 2024 {what} file: {source}")]
    Decode {
        path: PathBuf,
        what: &'static str,
        #[source]
        source: prost::DecodeError,
    },
    #[error("{path}: the map {map_id}.pb it names is not beside it or in a folder above")]
    NoMap { path: PathBuf, map_id: String },
    /// A value the model cannot take (e.g. an id 0, a bound with one point).
    #[error("{path}: {context}: {message}")]
    Invalid { path: PathBuf, context: String, message: String },
}

/// A scenario read from the three files, its planning problems and what was left out.
#[derive(Debug, Clone, PartialEq)]
pub struct Read2024 {
    pub scenario: Scenario,
    pub problems: PlanningProblemSet,
    pub warnings: Vec<String>,
}

/// An error of a part of the model: where, and what is wrong (the file is added by the caller).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Bad {
    pub context: String,
    pub message: String,
}

impl Bad {
    pub(crate) fn new(context: impl Into<String>, message: impl Into<String>) -> Self {
        Self { context: context.into(), message: message.into() }
    }
    fn in_file(self, path: &Path) -> ReadError {
        ReadError::Invalid { path: path.to_path_buf(), context: self.context, message: self.message }
    }
}

/// The three messages, decoded.
pub struct Messages {
    pub map: mp::CommonRoadMap,
    pub scenario: sc::CommonRoadScenario,
    pub dynamic: dy::CommonRoadDynamic,
}

/// The model of three decoded messages; `path` (the scenario file) is only used in messages.
pub fn read_messages(m: &Messages, path: &Path) -> Result<Read2024, ReadError> {
    let mut warnings = Vec::new();
    let header = scenario::header(&m.scenario.scenario_meta_information, &mut warnings).map_err(|b| b.in_file(path))?;
    let mut s = Scenario::new(header);
    s.location = map::location(&m.map.location);
    s.network = map::network(&m.map, &mut warnings).map_err(|b| b.in_file(path))?;
    s.environment_obstacles = map::environment_obstacles(&m.map, &mut warnings).map_err(|b| b.in_file(path))?;
    dynamic::apply_cycles(&mut s.network, &m.dynamic, &mut warnings).map_err(|b| b.in_file(path))?;
    s.static_obstacles = dynamic::static_obstacles(&m.dynamic, &mut warnings).map_err(|b| b.in_file(path))?;
    s.dynamic_obstacles = dynamic::dynamic_obstacles(&m.dynamic, &mut warnings).map_err(|b| b.in_file(path))?;
    let (problems, tags) = scenario::planning_problems(&m.scenario, &mut warnings).map_err(|b| b.in_file(path))?;
    s.tags = tags;
    Ok(Read2024 { scenario: s, problems, warnings })
}

/// Reads the three files' bytes.
pub fn read(map: &[u8], scenario: &[u8], dynamic: &[u8], path: &Path) -> Result<Read2024, ReadError> {
    let decode = |what, source| ReadError::Decode { path: path.to_path_buf(), what, source };
    let m = Messages {
        map: mp::CommonRoadMap::decode(map).map_err(|e| decode("map", e))?,
        scenario: sc::CommonRoadScenario::decode(scenario).map_err(|e| decode("scenario", e))?,
        dynamic: dy::CommonRoadDynamic::decode(dynamic).map_err(|e| decode("dynamic", e))?,
    };
    read_messages(&m, path)
}

fn read_bytes(path: &Path) -> Result<Vec<u8>, ReadError> {
    let io = |source| ReadError::Io { path: path.to_path_buf(), source };
    let len = std::fs::metadata(path).map_err(io)?.len();
    if len > MAX_FILE_BYTES {
        return Err(ReadError::TooLarge { path: path.to_path_buf(), bytes: len });
    }
    std::fs::read(path).map_err(io)
}

/// Whether `path` names a 2024 scenario file (`*-SC.pb`).
pub fn is_scenario_file(path: &Path) -> bool {
    path.file_name().and_then(|n| n.to_str()).is_some_and(|n| n.ends_with("-SC.pb"))
}

/// The dynamic and map files of the scenario file `scenario_path` (`NAME-SC.pb`): `NAME.pb`
/// beside it, and `<map id>.pb` beside it or in one of the folders above.
pub fn companion_files(scenario_path: &Path, scenario_bytes: &[u8]) -> Result<(PathBuf, PathBuf), ReadError> {
    let name = scenario_path.file_name().and_then(|n| n.to_str()).unwrap_or("");
    let stem = name.strip_suffix("-SC.pb").unwrap_or(name.trim_end_matches(".pb"));
    let dir = scenario_path.parent().unwrap_or(Path::new(""));
    let dynamic = dir.join(format!("{stem}.pb"));
    let decoded =
        sc::CommonRoadScenario::decode(scenario_bytes).map_err(|source| ReadError::Decode { path: scenario_path.to_path_buf(), what: "scenario", source })?;
    let map_name = format!("{}.pb", decoded.map_id);
    let map = dir
        .ancestors()
        .take(MAP_SEARCH_DEPTH + 1)
        .map(|d| d.join(&map_name))
        .find(|p| p.is_file())
        .ok_or_else(|| ReadError::NoMap { path: scenario_path.to_path_buf(), map_id: decoded.map_id.clone() })?;
    Ok((dynamic, map))
}

/// Reads a scenario from its scenario file `NAME-SC.pb` and the two files it goes with
/// ([`companion_files`]).
pub fn read_files(scenario_path: &Path) -> Result<Read2024, ReadError> {
    let scenario = read_bytes(scenario_path)?;
    let (dynamic_path, map_path) = companion_files(scenario_path, &scenario)?;
    let dynamic = read_bytes(&dynamic_path)?;
    let map = read_bytes(&map_path)?;
    read(&map, &scenario, &dynamic, scenario_path)
}

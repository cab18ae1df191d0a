//! The CommonRoad 2024 format: one scenario as three protobuf files, as commonroad-io 2026.1
//! reads them (`CommonRoadFileReader(filename_map=…, filename_scenario=…,
//! filename_dynamic=…).open_all()`):
//!
//! - the **map** (`CommonRoadMap`, [`encode_map`]): location, lanelets with their bounds and
//!   stop lines, traffic signs, traffic lights (position, colours, direction), intersections,
//!   environment obstacles;
//! - the **dynamic** file (`CommonRoadDynamic`): static and dynamic obstacles with their
//!   trajectories, and the traffic-light cycles;
//! - the **scenario** file (`CommonRoadScenario`): meta information, the planning problems with
//!   their goals (each carrying the scenario tags), the map's id and the dynamic file's id.
//!
//! The writer turns the 2020a model ([`Scenario`] + [`PlanningProblemSet`]) into the three so
//! that commonroad-io reads back the objects it reads from the 2020a file. A map is named by its
//! content (a hash of its bytes, [`MapFile::id`]), so one lanelet network is one map file
//! whichever scenario it comes with, and many scenario and dynamic files can refer to it. The
//! file names are commonroad-io's: `<map id>.pb`, and per scenario `<name>.pb` (dynamic) and
//! `<name>-SC.pb` (scenario).
//!
//! What the 2020a model holds and a 2024 file cannot say — an intersection's `isLeftOf`, a stop
//! line's reference to a light its lanelet does not refer to, more than one prediction id — is
//! a warning naming it, returned with the bytes. Deterministic: the messages are prost's
//! encoding of the proto2 definitions (fields in tag order, repeated scalars unpacked as proto2
//! says), built in the model's order, so the same model gives the same bytes.
//!
//! The message definitions come from commonroad-io 2026.1 (BSD-3-Clause): its wheel carries
//! them compiled into its `_pb2.py` modules; `proto/commonroad_2024.binpb` is that descriptor
//! set (`proto/README.md` says how it was extracted) and [`messages`] prost-build's types for it.

mod dynamic;
mod error;
mod map;
pub mod messages;
mod meta;
mod scenario;
mod sign_names;
mod signs;
mod values;

use prost::Message;

pub use error::WriteError;
pub use map::{encode_map, MapFile};

use crate::planning::PlanningProblemSet;
use crate::scenario::Scenario;

/// The first id of a map's own parts (bounds, stop lines, crossings; see `map.rs`). The
/// scenario's ids must lie below it: the readers register all of them in one id space.
pub const FIRST_MAP_PART_ID: u64 = 1_000_000_000;

/// The scenario and dynamic files of one scenario, for a map written apart.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScenarioFiles {
    /// `CommonRoadScenario`.
    pub scenario: Vec<u8>,
    /// `CommonRoadDynamic`.
    pub dynamic: Vec<u8>,
    /// What the two files cannot say of the model.
    pub warnings: Vec<String>,
}

/// All three files of a scenario.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Files2024 {
    pub map: MapFile,
    pub scenario: Vec<u8>,
    pub dynamic: Vec<u8>,
    /// The map's warnings, then the scenario's.
    pub warnings: Vec<String>,
}

/// The three files of `scenario`; at least one planning problem is needed.
pub fn write(scenario: &Scenario, problems: &PlanningProblemSet) -> Result<Files2024, WriteError> {
    let map = encode_map(scenario)?;
    let files = encode_scenario(scenario, problems, &map.id)?;
    let mut warnings = map.warnings.clone();
    warnings.extend(files.warnings);
    Ok(Files2024 { map, scenario: files.scenario, dynamic: files.dynamic, warnings })
}

/// The scenario and dynamic files of `scenario`, referring to the map `map_id` (the
/// [`MapFile::id`] of [`encode_map`] for the same scenario).
pub fn encode_scenario(scenario: &Scenario, problems: &PlanningProblemSet, map_id: &str) -> Result<ScenarioFiles, WriteError> {
    let highest = scenario.max_id().max(problems.max_id());
    if highest >= FIRST_MAP_PART_ID {
        return Err(WriteError::IdInMapPartRange { context: "the scenario".into(), id: highest });
    }
    let mut warnings = Vec::new();
    let meta = meta::scenario_meta(&scenario.header, &mut warnings)?;
    let dynamic = dynamic::dynamic_message(scenario, meta.clone())?.encode_to_vec();
    let scenario = scenario::scenario_message(scenario, problems, meta, map_id)?.encode_to_vec();
    Ok(ScenarioFiles { scenario, dynamic, warnings })
}

/// The scenario file's name for a scenario named `stem`: `<stem>-SC.pb` (commonroad-io's).
pub fn scenario_file_name(stem: &str) -> String {
    format!("{stem}-SC.pb")
}

/// The dynamic file's name for a scenario named `stem`: `<stem>.pb` (commonroad-io's).
pub fn dynamic_file_name(stem: &str) -> String {
    format!("{stem}.pb")
}

/// The map id a scenario file refers to (`CommonRoadScenario.map_id`); `None` when `bytes` is
/// not a complete scenario file.
pub fn map_id_of_scenario(bytes: &[u8]) -> Option<String> {
    messages::commonroad_scenario::CommonRoadScenario::decode(bytes).ok().map(|s| s.map_id)
}

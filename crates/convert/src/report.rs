//! What a conversion tells the user, as data (serialised with serde for `--report`).

use std::path::PathBuf;

use serde::Serialize;

/// The stage of the pipeline a warning or failure comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// Reading the OpenSCENARIO file (parameters, catalogs, distributions).
    Load,
    /// Reading the OpenDRIVE file named by `RoadNetwork/LogicFile`.
    RoadNetwork,
    /// OpenDRIVE → lanelets.
    Map,
    /// Running the storyboard.
    Engine,
    /// Trace → obstacles, planning problem, checks.
    Build,
    /// XML bytes and the output file.
    Write,
    /// The per-scenario time limit.
    Timeout,
    /// The picture beside the output (`--render`); only ever a warning.
    Render,
}

impl Stage {
    /// The stage's name as the report writes it (`road_network`, …).
    pub fn as_str(self) -> &'static str {
        match self {
            Stage::Load => "load",
            Stage::RoadNetwork => "road_network",
            Stage::Map => "map",
            Stage::Engine => "engine",
            Stage::Build => "build",
            Stage::Write => "write",
            Stage::Timeout => "timeout",
            Stage::Render => "render",
        }
    }
}

/// A warning of one stage.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StageWarning {
    pub stage: Stage,
    pub message: String,
}

/// Why a scenario was not converted.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Failure {
    pub stage: Stage,
    pub message: String,
}

/// Milliseconds spent per stage (wall clock).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Timings {
    pub load_ms: f64,
    pub road_network_ms: f64,
    pub map_ms: f64,
    pub engine_ms: f64,
    pub build_ms: f64,
    pub write_ms: f64,
    pub total_ms: f64,
}

/// The parameter set of one variation of a distribution file.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Variation {
    /// 1-based; also the configuration id of the benchmark id and the `_<k>` of the file name.
    pub index: u64,
    /// The scenario file the distribution varies.
    pub scenario_file: PathBuf,
    pub parameters: Vec<(String, String)>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    Converted,
    Failed,
    /// Its output files were all there from an earlier run, so it was not converted again
    /// (`--resume`).
    Complete,
}

impl Status {
    /// The word the report and the table use.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Converted => "converted",
            Status::Failed => "failed",
            Status::Complete => "complete",
        }
    }
}

/// Facts about a converted scenario, for the report.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Facts {
    pub benchmark_id: Option<String>,
    pub ego: Option<String>,
    pub lanelets: usize,
    pub obstacles: usize,
    /// Simulated duration, s.
    pub duration_s: Option<f64>,
    pub tags: Vec<String>,
}

/// One scenario (or one variation) of a batch.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScenarioReport {
    /// The file given or found (scenario or distribution file).
    pub input: PathBuf,
    /// Group of the summary table (the input's folder).
    pub folder: String,
    /// The output file: the XML file (2020a), or the scenario file `<name>-SC.pb` (2024).
    pub output: Option<PathBuf>,
    /// The dynamic file `<name>.pb` (2024 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamic: Option<PathBuf>,
    /// The map file the scenario file refers to, shared with every scenario of the batch on the
    /// same lanelet network (2024 only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub map: Option<PathBuf>,
    pub variation: Option<Variation>,
    pub status: Status,
    pub failure: Option<Failure>,
    pub warnings: Vec<StageWarning>,
    pub timings: Timings,
    /// Benchmark id, ego, counts, duration and tags (in the JSON report as fields of their own).
    #[serde(flatten)]
    pub facts: Facts,
    /// The picture written beside the output (`--render`).
    pub picture: Option<PathBuf>,
}

impl ScenarioReport {
    /// The report of `input` (in summary group `folder`) before anything is known of its
    /// conversion: no output, no counts, no warnings.
    pub fn new(input: PathBuf, folder: String, variation: Option<Variation>, status: Status) -> ScenarioReport {
        ScenarioReport {
            input,
            folder,
            output: None,
            dynamic: None,
            map: None,
            variation,
            status,
            failure: None,
            warnings: Vec::new(),
            timings: Timings::default(),
            facts: Facts::default(),
            picture: None,
        }
    }
}

/// A file of a batch that is not a scenario.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Skipped {
    pub path: PathBuf,
    pub reason: String,
}

/// One row of the summary table (the paper's Table II): per folder.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FolderSummary {
    pub folder: String,
    pub scenarios: usize,
    pub converted: usize,
    /// converted / scenarios, 0..=1.
    pub success_rate: f64,
    /// Mean total conversion time of the converted scenarios, ms.
    pub mean_conversion_ms: Option<f64>,
    /// Mean simulated duration of the converted scenarios, s.
    pub mean_duration_s: Option<f64>,
}

/// Everything `--report` writes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BatchReport {
    pub scenarios: Vec<ScenarioReport>,
    pub skipped: Vec<Skipped>,
    pub summary: Vec<FolderSummary>,
    /// Conversions of the whole batch, all shards together (`scenarios` holds one shard's).
    pub planned: usize,
}

impl BatchReport {
    pub fn failed(&self) -> usize {
        self.scenarios.iter().filter(|s| s.status == Status::Failed).count()
    }
}

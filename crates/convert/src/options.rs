//! Everything a conversion can be told, with the paper's defaults.

use std::fmt;
use std::str::FromStr;

use commonroad::Date;

use crate::ego::EgoChoice;
use crate::goal::GoalOptions;
use crate::header::check_country;

/// Options of one conversion (and of every scenario of a batch).
#[derive(Debug, Clone, PartialEq)]
pub struct ConvertOptions {
    /// CommonRoad time step, s (default 0.1).
    pub dt: f64,
    /// Engine step, s (default 0.01).
    pub step: f64,
    /// Simulated time after which a run stops, s (default 60).
    pub max_time: f64,
    pub ego: EgoChoice,
    /// Leave the ego out of the obstacles (motion-planning benchmarks).
    pub drop_ego: bool,
    pub goal: GoalOptions,
    /// Country code of the benchmark id (default `ZAM`).
    pub country: String,
    /// `None`: the OpenSCENARIO FileHeader's author (or "osc2cr" if it is empty).
    pub author: Option<String>,
    pub affiliation: String,
    /// `None`: "OpenSCENARIO <file name>, converted by osc2cr".
    pub source: Option<String>,
    /// `None`: the FileHeader's date, else 1970-01-01 (never today: same input, same bytes).
    pub date: Option<Date>,
    /// Global parameter overrides (`--param NAME=VALUE`), applied to every scenario.
    pub parameters: Vec<(String, String)>,
    /// Seed of stochastic parameter distributions (`None`: the file's own).
    pub seed: Option<u64>,
    /// Most parameter variations converted per distribution file (default 100).
    pub max_variations: u64,
    /// Largest distance between a lanelet bound and the exact lane border, m (`None`: the
    /// map converter's default). Coarser means fewer bound points and smaller files.
    pub map_tolerance: Option<f64>,
    /// Seed of esmini's random generator in the engine (esmini's `--seed`, default 0 as in the
    /// reference traces): it decides ties esmini leaves to chance, e.g. at junctions.
    pub engine_seed: u32,
    /// Wall-clock instant after which the engine stops this conversion (set by a batch's
    /// per-scenario time limit; `None`: no limit).
    pub deadline: Option<std::time::Instant>,
    /// Read references to what does not exist (entities, storyboard elements, parameters,
    /// variables, roads, lanes) and distributions that cannot be sampled as warnings, passing
    /// them over as the engine can; by default (`false`) they stop the file with an error.
    pub lenient: bool,
    /// The CommonRoad format written (default 2020a XML).
    pub format: OutputFormat,
}

/// Which CommonRoad format a conversion writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum OutputFormat {
    /// One XML file per scenario (`commonRoadVersion="2020a"`), the format most tools read.
    #[default]
    Xml2020a,
    /// Three protobuf files: a map (shared by every scenario on the same lanelet network), a
    /// scenario file and a dynamic file (commonroad-io 2024.x and later).
    Protobuf2024,
}

impl FromStr for OutputFormat {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.trim() {
            "2020a" => Ok(OutputFormat::Xml2020a),
            "2024" => Ok(OutputFormat::Protobuf2024),
            other => Err(format!("the CommonRoad format is 2020a or 2024, got {other:?}")),
        }
    }
}

impl fmt::Display for OutputFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            OutputFormat::Xml2020a => "2020a",
            OutputFormat::Protobuf2024 => "2024",
        })
    }
}

impl Default for ConvertOptions {
    fn default() -> Self {
        Self {
            dt: 0.1,
            step: 0.01,
            max_time: 60.0,
            ego: EgoChoice::default(),
            drop_ego: false,
            goal: GoalOptions::default(),
            country: "ZAM".to_string(),
            author: None,
            affiliation: String::new(),
            source: None,
            date: None,
            parameters: Vec::new(),
            seed: None,
            max_variations: 100,
            map_tolerance: None,
            engine_seed: 0,
            deadline: None,
            lenient: false,
            format: OutputFormat::Xml2020a,
        }
    }
}

/// Smallest CommonRoad step accepted (bounds the number of states a file can get).
const MIN_DT: f64 = 1e-3;

impl ConvertOptions {
    /// Checks values no conversion could use; the message names the option.
    pub fn check(&self) -> Result<(), String> {
        if !(self.dt.is_finite() && self.dt >= MIN_DT) {
            return Err(format!("--dt must be at least {MIN_DT} s, got {}", self.dt));
        }
        if !(self.step.is_finite() && self.step > 0.0 && self.step <= self.dt) {
            return Err(format!("--step must be > 0 s and at most --dt ({} s), got {}", self.dt, self.step));
        }
        if !(self.max_time.is_finite() && self.max_time > 0.0) {
            return Err(format!("--max-time must be > 0 s, got {}", self.max_time));
        }
        let g = &self.goal;
        for (name, v) in [("--goal-length", g.length), ("--goal-width", g.width)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(format!("{name} must be > 0 m, got {v}"));
            }
        }
        for (name, v) in [("--goal-speed-margin", g.speed_margin), ("--goal-orientation-margin", g.orientation_margin)] {
            if let Some(v) = v {
                if !(v.is_finite() && v >= 0.0) {
                    return Err(format!("{name} must be >= 0, got {v}"));
                }
            }
        }
        if let Some(t) = self.map_tolerance {
            if !(t.is_finite() && t > 0.0) {
                return Err(format!("--map-tolerance must be > 0 m, got {t}"));
            }
        }
        check_country(&self.country)
    }
}

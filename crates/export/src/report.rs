//! What a batch tells the user, as data: a report per scenario (serialised for `--report`),
//! the maps written with their warnings, and the summary per folder (rows and their cells; the
//! CLI draws the table).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::scenario::Facts;

/// How a scenario fared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    Exported,
    Failed,
}

/// The step a failure comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// Reading the CommonRoad file(s).
    Read,
    /// The lanelet network as OpenDRIVE.
    Map,
    /// The OpenSCENARIO document.
    Scenario,
    /// Writing the files.
    Write,
}

/// Why a scenario was not exported.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Failure {
    pub stage: Stage,
    pub message: String,
}

/// One scenario of a batch.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    pub input: PathBuf,
    /// The summary's group: the folder searched and the file's sub-folder.
    pub folder: String,
    pub status: Status,
    /// The `.xosc` written.
    pub output: Option<PathBuf>,
    /// The map's file name (at the top of the output folder).
    pub map: Option<String>,
    pub failure: Option<Failure>,
    pub warnings: Vec<String>,
    pub facts: Option<Facts>,
    /// Wall time of the scenario (reading, map, document, writing), ms.
    pub time_ms: f64,
}

/// A map of the batch: its file, how many scenarios use it, its warnings.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MapReport {
    pub file: String,
    pub scenarios: usize,
    pub warnings: Vec<String>,
}

/// A file a batch passed over, and why.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Skipped {
    pub path: PathBuf,
    pub reason: String,
}

/// A row of the summary table.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SummaryRow {
    pub folder: String,
    pub scenarios: usize,
    pub exported: usize,
    pub success_rate: f64,
    pub mean_time_ms: Option<f64>,
    /// Obstacles of the exported scenarios.
    pub obstacles: usize,
}

/// The summary rows of `reports`: one per folder, sorted, and "all" when there are several.
pub fn summarise(reports: &[Report]) -> Vec<SummaryRow> {
    #[derive(Default)]
    struct Sums {
        scenarios: usize,
        exported: usize,
        time: f64,
        obstacles: usize,
    }
    let add = |s: &mut Sums, r: &Report| {
        s.scenarios += 1;
        if r.status == Status::Exported {
            s.exported += 1;
            s.time += r.time_ms;
            s.obstacles += r.facts.as_ref().map_or(0, |f| f.dynamic_obstacles + f.static_obstacles + f.environment_obstacles);
        }
    };
    let mut folders: BTreeMap<&str, Sums> = BTreeMap::new();
    let mut all = Sums::default();
    for r in reports {
        add(folders.entry(r.folder.as_str()).or_default(), r);
        add(&mut all, r);
    }
    let row = |folder: &str, s: &Sums| SummaryRow {
        folder: folder.to_string(),
        scenarios: s.scenarios,
        exported: s.exported,
        success_rate: if s.scenarios == 0 { 0.0 } else { s.exported as f64 / s.scenarios as f64 },
        mean_time_ms: (s.exported > 0).then(|| s.time / s.exported as f64),
        obstacles: s.obstacles,
    };
    let mut rows: Vec<SummaryRow> = folders.iter().map(|(f, s)| row(f, s)).collect();
    if rows.len() > 1 {
        rows.push(row("all", &all));
    }
    rows
}

impl SummaryRow {
    /// The table's header (the CLI draws the table).
    pub const HEADER: [&'static str; 6] = ["folder", "scenarios", "exported", "success", "mean time", "obstacles"];

    /// The row's cells, in the order of [`SummaryRow::HEADER`].
    pub fn cells(&self) -> Vec<String> {
        vec![
            self.folder.clone(),
            self.scenarios.to_string(),
            self.exported.to_string(),
            format!("{:.1} %", 100.0 * self.success_rate),
            self.mean_time_ms.map_or("-".into(), |v| format!("{v:.1} ms")),
            self.obstacles.to_string(),
        ]
    }
}

/// What a batch did; serialised, it is the JSON report of `--report` (the warning count is the
/// sum of what the reports list, so the report leaves it out).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BatchTotals {
    pub exported: usize,
    pub failed: usize,
    #[serde(skip)]
    pub warnings: usize,
    pub skipped: Vec<Skipped>,
    pub summary: Vec<SummaryRow>,
    pub maps: Vec<MapReport>,
    /// Every report, in input order.
    #[serde(rename = "scenarios")]
    pub reports: Vec<Report>,
}

impl BatchTotals {
    /// Writes the JSON report, whole or not at all.
    pub fn write(&self, path: &Path) -> Result<(), String> {
        let text = serde_json::to_string_pretty(self).map_err(|e| format!("report: {e}"))?;
        commonroad::xml::write_atomic(path, text.as_bytes()).map_err(|e| e.to_string())
    }
}

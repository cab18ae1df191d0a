//! The report files of a batch, written as the conversions come in, so that a batch of any
//! size keeps no list of its reports:
//!
//! - [`JsonReport`] (`--report FILE`): `{"scenarios": [...], "skipped": [...], "summary": [...],
//!   "planned": N}`, one scenario per line, written to a temporary file beside `FILE` and renamed
//!   to it when the batch ends (whole or not at all, like every output; a device or pipe such as
//!   `/dev/null` is written in place, never renamed over);
//! - [`Table`] (`--table FILE`): one tab-separated line per conversion in batch order (status,
//!   stage, files, counts, time, the failure's first line, the parameters), flushed line by line,
//!   so that it shows how far a running batch is and what an interrupted one did.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use crate::report::{FolderSummary, ScenarioReport, Skipped};

fn io_error(path: &Path, e: impl std::fmt::Display) -> String {
    format!("cannot write {}: {e}", path.display())
}

/// The JSON report, streamed.
pub struct JsonReport {
    path: PathBuf,
    tmp: PathBuf,
    /// The target is a device or pipe, written in place (`tmp` is the target itself).
    in_place: bool,
    out: BufWriter<File>,
    first: bool,
}

impl JsonReport {
    /// Starts the report that will be `path`.
    pub fn create(path: &Path) -> Result<Self, String> {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "report".into());
        let in_place = commonroad::xml::is_special_file(path);
        let tmp = if in_place { path.to_path_buf() } else { path.with_file_name(format!(".{name}.{}.stream.tmp", std::process::id())) };
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| io_error(path, e))?;
        }
        let file = File::create(&tmp).map_err(|e| io_error(&tmp, e))?;
        let mut out = BufWriter::new(file);
        out.write_all(b"{\n\"scenarios\": [").map_err(|e| io_error(&tmp, e))?;
        Ok(JsonReport { path: path.to_path_buf(), tmp, in_place, out, first: true })
    }

    /// Adds one conversion.
    pub fn add(&mut self, report: &ScenarioReport) -> Result<(), String> {
        let sep: &[u8] = if self.first { b"\n" } else { b",\n" };
        self.first = false;
        self.out.write_all(sep).map_err(|e| io_error(&self.tmp, e))?;
        serde_json::to_writer(&mut self.out, report).map_err(|e| io_error(&self.tmp, e))
    }

    /// Ends the report with the skipped files, the summary and the number of conversions
    /// planned, and puts it in place.
    pub fn finish(mut self, skipped: &[Skipped], summary: &[FolderSummary], planned: usize) -> Result<(), String> {
        let tail = (|| -> Result<(), Box<dyn std::error::Error>> {
            self.out.write_all(b"\n],\n\"skipped\": ")?;
            serde_json::to_writer(&mut self.out, skipped)?;
            self.out.write_all(b",\n\"summary\": ")?;
            serde_json::to_writer_pretty(&mut self.out, summary)?;
            write!(self.out, ",\n\"planned\": {planned}\n}}\n")?;
            self.out.flush()?;
            Ok(())
        })();
        let result = tail.map_err(|e| io_error(&self.tmp, e));
        if self.in_place {
            return result;
        }
        let result = result.and_then(|()| std::fs::rename(&self.tmp, &self.path).map_err(|e| io_error(&self.path, e)));
        if result.is_err() {
            let _ = std::fs::remove_file(&self.tmp);
        }
        result
    }
}

/// The per-conversion table, streamed.
pub struct Table {
    path: PathBuf,
    out: BufWriter<File>,
}

/// The table's columns.
pub const TABLE_COLUMNS: [&str; 13] =
    ["position", "input", "variation", "status", "stage", "output", "map", "lanelets", "obstacles", "duration_s", "total_ms", "warnings", "message"];

/// Tabs and line ends would break a row: they become spaces.
fn cell(s: &str) -> String {
    s.replace(['\t', '\n', '\r'], " ")
}

impl Table {
    /// Starts the table `path` (replacing an earlier one) with its header line.
    pub fn create(path: &Path) -> Result<Self, String> {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(|e| io_error(path, e))?;
        }
        let file = File::create(path).map_err(|e| io_error(path, e))?;
        let mut table = Table { path: path.to_path_buf(), out: BufWriter::new(file) };
        let mut header = TABLE_COLUMNS.join("\t");
        header.push_str("\tparameters\n");
        table.out.write_all(header.as_bytes()).map_err(|e| io_error(path, e))?;
        Ok(table)
    }

    /// Adds the line of conversion `position` (0-based, in the whole batch's order).
    pub fn add(&mut self, position: usize, r: &ScenarioReport) -> Result<(), String> {
        let opt = |p: &Option<PathBuf>| p.as_ref().map(|p| p.display().to_string()).unwrap_or_default();
        let message = r.failure.as_ref().map(|f| f.message.lines().next().unwrap_or("").to_string()).unwrap_or_default();
        let parameters = r.variation.as_ref().map(|v| v.parameters.iter().map(|(n, v)| format!("{n}={v}")).collect::<Vec<_>>().join(";")).unwrap_or_default();
        let row = [
            position.to_string(),
            r.input.display().to_string(),
            r.variation.as_ref().map(|v| v.index.to_string()).unwrap_or_default(),
            r.status.as_str().to_string(),
            r.failure.as_ref().map(|f| f.stage.as_str().to_string()).unwrap_or_default(),
            opt(&r.output),
            opt(&r.map),
            r.facts.lanelets.to_string(),
            r.facts.obstacles.to_string(),
            r.facts.duration_s.map(|d| format!("{d:.2}")).unwrap_or_default(),
            format!("{:.1}", r.timings.total_ms),
            r.warnings.len().to_string(),
            message,
            parameters,
        ];
        let line: Vec<String> = row.iter().map(|c| cell(c)).collect();
        writeln!(self.out, "{}", line.join("\t")).map_err(|e| io_error(&self.path, e))?;
        // a line at a time: the table shows how far the batch is
        self.out.flush().map_err(|e| io_error(&self.path, e))
    }
}

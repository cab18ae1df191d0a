//! The summary table, per folder, like the paper's Table II: how many scenarios, success rate,
//! mean conversion time (wall clock, per converted scenario), mean simulated time (how long the
//! converted scenarios run).

use std::collections::BTreeMap;
use std::fmt::Write as _;

use crate::report::{FolderSummary, ScenarioReport, Status};

/// One row per folder, folders sorted by name, plus a last row "all" when there are several.
pub fn summarise(reports: &[ScenarioReport]) -> Vec<FolderSummary> {
    let mut s = Summary::default();
    for r in reports {
        s.add(r);
    }
    s.rows()
}

/// The summary table built as reports come in (a batch of 100,000 variations keeps no list of
/// them): per folder, counts and the sums the means need. A conversion found complete from an
/// earlier run (`--resume`) counts as converted but has no time or duration to average.
#[derive(Debug, Clone, Default)]
pub struct Summary {
    folders: BTreeMap<String, Sums>,
    all: Sums,
}

#[derive(Debug, Clone, Default)]
struct Sums {
    scenarios: usize,
    converted: usize,
    time_ms: (f64, usize),
    duration_s: (f64, usize),
}

impl Sums {
    fn add(&mut self, r: &ScenarioReport) {
        self.scenarios += 1;
        match r.status {
            Status::Converted => {
                self.converted += 1;
                self.time_ms.0 += r.timings.total_ms;
                self.time_ms.1 += 1;
                if let Some(d) = r.facts.duration_s {
                    self.duration_s.0 += d;
                    self.duration_s.1 += 1;
                }
            }
            Status::Complete => self.converted += 1,
            Status::Failed => {}
        }
    }

    fn row(&self, folder: &str) -> FolderSummary {
        let mean = |(sum, n): (f64, usize)| (n > 0).then(|| sum / n as f64);
        FolderSummary {
            folder: folder.to_string(),
            scenarios: self.scenarios,
            converted: self.converted,
            success_rate: if self.scenarios == 0 { 0.0 } else { self.converted as f64 / self.scenarios as f64 },
            mean_conversion_ms: mean(self.time_ms),
            mean_duration_s: mean(self.duration_s),
        }
    }
}

impl Summary {
    /// Counts one report (in batch order, so that the sums are those of a list).
    pub fn add(&mut self, r: &ScenarioReport) {
        self.folders.entry(r.folder.clone()).or_default().add(r);
        self.all.add(r);
    }

    /// One row per folder, sorted by name, and a row "all" when there are several.
    pub fn rows(&self) -> Vec<FolderSummary> {
        let mut rows: Vec<FolderSummary> = self.folders.iter().map(|(f, s)| s.row(f)).collect();
        if rows.len() > 1 {
            rows.push(self.all.row("all"));
        }
        rows
    }
}

/// The table as aligned text.
pub fn render(rows: &[FolderSummary]) -> String {
    // the conversion's wall-clock time, and how long the scenario runs in simulated time
    let header = ["folder", "scenarios", "converted", "success", "mean conversion time", "mean simulated time"];
    let cells: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                r.folder.clone(),
                r.scenarios.to_string(),
                r.converted.to_string(),
                format!("{:.1} %", 100.0 * r.success_rate),
                r.mean_conversion_ms.map_or("-".into(), |v| format!("{v:.1} ms")),
                r.mean_duration_s.map_or("-".into(), |v| format!("{v:.1} s")),
            ]
        })
        .collect();
    render_table(&header, &cells)
}

/// A table as aligned text: the header, a rule, a line per row; the first column left-aligned,
/// the others right-aligned (`osc2cr export`'s summary is drawn with it too).
pub fn render_table(header: &[&str], cells: &[Vec<String>]) -> String {
    let mut width: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for c in cells {
        for (w, s) in width.iter_mut().zip(c) {
            *w = (*w).max(s.chars().count());
        }
    }
    let mut out = String::new();
    let line = |out: &mut String, c: &[String]| {
        for (i, (s, w)) in c.iter().zip(&width).enumerate() {
            let pad = w.saturating_sub(s.chars().count());
            if i == 0 {
                let _ = write!(out, "{s}{}", " ".repeat(pad));
            } else {
                let _ = write!(out, "  {}{s}", " ".repeat(pad));
            }
        }
        out.push('\n');
    };
    line(&mut out, &header.iter().map(|h| h.to_string()).collect::<Vec<_>>());
    let rule: Vec<String> = width.iter().map(|w| "-".repeat(*w)).collect();
    line(&mut out, &rule);
    for c in cells {
        line(&mut out, c);
    }
    out
}

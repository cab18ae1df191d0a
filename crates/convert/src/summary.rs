//! The summary table, per folder, like the paper's Table II: how many scenarios, success rate,
//! mean conversion time, mean simulated duration.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use crate::report::{FolderSummary, ScenarioReport, Status};

/// One row per folder, folders sorted by name, plus a last row "all" when there are several.
pub fn summarise(reports: &[ScenarioReport]) -> Vec<FolderSummary> {
    let mut groups: BTreeMap<&str, Vec<&ScenarioReport>> = BTreeMap::new();
    for r in reports {
        groups.entry(r.folder.as_str()).or_default().push(r);
    }
    let mut rows: Vec<FolderSummary> = groups
        .into_iter()
        .map(|(folder, rs)| row(folder, &rs))
        .collect();
    if rows.len() > 1 {
        let all: Vec<&ScenarioReport> = reports.iter().collect();
        rows.push(row("all", &all));
    }
    rows
}

fn row(folder: &str, rs: &[&ScenarioReport]) -> FolderSummary {
    let ok: Vec<&&ScenarioReport> = rs.iter().filter(|r| r.status == Status::Converted).collect();
    let mean = |v: Vec<f64>| (!v.is_empty()).then(|| v.iter().sum::<f64>() / v.len() as f64);
    FolderSummary {
        folder: folder.to_string(),
        scenarios: rs.len(),
        converted: ok.len(),
        success_rate: if rs.is_empty() {
            0.0
        } else {
            ok.len() as f64 / rs.len() as f64
        },
        mean_conversion_ms: mean(ok.iter().map(|r| r.timings.total_ms).collect()),
        mean_duration_s: mean(ok.iter().filter_map(|r| r.duration_s).collect()),
    }
}

/// The table as aligned text.
pub fn render(rows: &[FolderSummary]) -> String {
    let header = ["folder", "scenarios", "converted", "success", "mean time", "mean duration"];
    let cells: Vec<[String; 6]> = rows
        .iter()
        .map(|r| {
            [
                r.folder.clone(),
                r.scenarios.to_string(),
                r.converted.to_string(),
                format!("{:.1} %", 100.0 * r.success_rate),
                r.mean_conversion_ms
                    .map_or("-".into(), |v| format!("{v:.1} ms")),
                r.mean_duration_s.map_or("-".into(), |v| format!("{v:.1} s")),
            ]
        })
        .collect();
    let mut width = header.map(str::len);
    for c in &cells {
        for (w, s) in width.iter_mut().zip(c) {
            *w = (*w).max(s.chars().count());
        }
    }
    let mut out = String::new();
    let line = |out: &mut String, c: &[String]| {
        for (i, (s, w)) in c.iter().zip(width).enumerate() {
            let pad = w.saturating_sub(s.chars().count());
            if i == 0 {
                let _ = write!(out, "{s}{}", " ".repeat(pad));
            } else {
                let _ = write!(out, "  {}{s}", " ".repeat(pad));
            }
        }
        out.push('\n');
    };
    line(&mut out, &header.map(String::from));
    let rule: Vec<String> = width.iter().map(|w| "-".repeat(*w)).collect();
    line(&mut out, &rule);
    for c in &cells {
        line(&mut out, c);
    }
    out
}

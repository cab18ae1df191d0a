//! Running esmini 3.6.0 (when the user has it) on a scenario and reading its CSV log into
//! states — the same reduction as `../shared/tools/esmini/make_reference.py`: the columns
//! `TimeStamp`, `Entity_Name`, `World_Position_X/Y`, `World_Heading_Angle`, `Current_Speed`.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::compare::{State, TraceBuilder, Traces};

/// What esmini made of a scenario: its states and the error lines of its log (a scenario the
/// generator wrote well gives none).
#[derive(Debug, Clone, PartialEq)]
pub struct EsminiRun {
    pub traces: Traces,
    pub log_errors: Vec<String>,
}

/// Runs `esmini` headless at a 0.01 s step on `xosc` (its stop trigger ends it; `wall` kills
/// it), logging to `csv`. `Err` says why there is no trace.
pub fn run(esmini: &Path, xosc: &Path, csv: &Path, wall: Duration) -> Result<EsminiRun, String> {
    let dir = xosc.parent().unwrap_or(Path::new("."));
    let mut child = Command::new(esmini)
        .args(["--headless", "--fixed_timestep", "0.01", "--seed", "0", "--osc"])
        .arg(xosc)
        .arg("--csv_logger")
        .arg(csv)
        .arg("--logfile_path")
        .arg(csv.with_extension("log"))
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| format!("cannot start {}: {e}", esmini.display()))?;
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break s,
            Ok(None) if start.elapsed() > wall => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!("esmini did not finish within {} s", wall.as_secs()));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => return Err(e.to_string()),
        }
    };
    let log = std::fs::read_to_string(csv.with_extension("log")).unwrap_or_default();
    let log_errors: Vec<String> = log.lines().filter(|l| l.contains("[error]")).map(|l| l.trim().to_string()).collect();
    if !status.success() {
        let why = log_errors.last().map(|e| format!(": {e}")).unwrap_or_default();
        return Err(format!("esmini exited with {status}{why}"));
    }
    let text = std::fs::read_to_string(csv).map_err(|e| format!("no esmini log: {e}"))?;
    let traces = parse_csv(&text)?;
    if traces.is_empty() {
        return Err("esmini logged no state".into());
    }
    if let Some(why) = non_finite(&traces) {
        return Err(why);
    }
    Ok(EsminiRun { traces, log_errors })
}

/// Why a log is no reference: esmini 3.6.0 writes NaN positions where its own arithmetic fails
/// (a road-frame LateralDistanceAction whose actor stands at a dead end, for one). What follows
/// is esmini's undefined state, not a behaviour to match (and the engine never writes a
/// non-finite pose), so such a run is not compared. None when every position is finite.
pub fn non_finite(traces: &Traces) -> Option<String> {
    traces.iter().find_map(|(name, states)| {
        let s = states.iter().find(|s| !s.x.is_finite() || !s.y.is_finite())?;
        Some(format!("esmini logged a non-finite position ({name} at {:.2} s): no reference to compare", s.t))
    })
}

/// esmini's CSV log as states per entity.
pub fn parse_csv(text: &str) -> Result<Traces, String> {
    let mut header: Option<(usize, usize, [usize; 4])> = None;
    let mut out = TraceBuilder::default();
    for line in text.lines() {
        let parts: Vec<&str> = line.split(',').map(str::trim).collect();
        let Some((n0, block, cols)) = header else {
            if parts.len() > 2 && parts[1].contains("TimeStamp") {
                let names: Vec<usize> = parts.iter().enumerate().filter(|(_, p)| p.contains("_Name") && p.contains("ntit")).map(|(i, _)| i).collect();
                let Some(&n0) = names.first() else { return Err("esmini log without entity columns".into()) };
                let block = if names.len() > 1 { names[1] - n0 } else { parts.iter().filter(|p| !p.is_empty()).count() - n0 };
                let find = |key: &str| -> Option<usize> {
                    (n0..n0 + block)
                        .find(|&i| {
                            let p = parts.get(i).copied().unwrap_or("");
                            let p = p.trim_start_matches('#').trim_start_matches(|c: char| c.is_ascii_digit()).trim();
                            p.split(' ').next() == Some(key) || p.split('[').next().map(str::trim) == Some(key)
                        })
                        .map(|i| i - n0)
                };
                let cols = [
                    find("World_Position_X").ok_or("no World_Position_X")?,
                    find("World_Position_Y").ok_or("no World_Position_Y")?,
                    find("World_Heading_Angle").ok_or("no World_Heading_Angle")?,
                    find("Current_Speed").ok_or("no Current_Speed")?,
                ];
                header = Some((n0, block, cols));
            }
            continue;
        };
        if parts.len() < 3 || !parts[0].chars().all(|c| c.is_ascii_digit()) || parts[0].is_empty() {
            continue;
        }
        let Ok(t) = parts[1].parse::<f64>() else { continue };
        let mut k = n0;
        while k + block <= parts.len() && !parts[k].is_empty() {
            let get = |j: usize| parts.get(k + j).and_then(|v| v.parse::<f64>().ok());
            if let (Some(x), Some(y), Some(h), Some(v)) = (get(cols[0]), get(cols[1]), get(cols[2]), get(cols[3])) {
                // the reference traces keep two decimals of time
                let t = (t * 100.0).round() / 100.0;
                out.push(parts[k], State { t, x, y, h, v });
            }
            k += block;
        }
    }
    Ok(out.finish())
}

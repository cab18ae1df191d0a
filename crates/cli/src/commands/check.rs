//! `osc2cr check`: what is wrong with OpenSCENARIO files, without converting them — every file
//! of the inputs (folders are searched) is read as `convert` reads it, its road network loaded
//! and its positions checked against it, and each finding printed with severity and
//! file:line:col. Errors are what stops `convert` (malformed XML or values, a missing catalog
//! entry, a reference to what does not exist); warnings are what it approximates or ignores.

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::shared_options::ParamArgs;
use crate::Failure;

mod convert_stops;

#[derive(clap::Args)]
pub(crate) struct CheckArgs {
    /// OpenSCENARIO files or folders (searched for .xosc, recursively; catalogs in a folder are
    /// checked through the scenarios that use them, a catalog named alone is read alone).
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Print the findings as JSON (an array of {file, line, column, severity, message}).
    #[arg(long)]
    pub json: bool,
    /// Also list warnings (by default only errors and a count of warnings are printed).
    #[arg(short, long)]
    pub verbose: bool,
    #[command(flatten)]
    pub params: ParamArgs,
}

#[derive(Debug, Clone, Serialize)]
struct Finding {
    file: String,
    line: u32,
    column: u32,
    severity: &'static str,
    message: String,
}

fn finding(severity: &'static str, file: &Path, line: u32, column: u32, message: impl Into<String>) -> Finding {
    Finding { file: file.display().to_string(), line, column, severity, message: message.into() }
}

fn xosc_files(inputs: &[PathBuf]) -> Result<Vec<PathBuf>, Failure> {
    let mut out = Vec::new();
    for i in inputs {
        if i.is_dir() {
            let mut stack = vec![i.clone()];
            let mut found = Vec::new();
            while let Some(d) = stack.pop() {
                let entries = std::fs::read_dir(&d).map_err(|e| Failure::input(format!("{}: {e}", d.display())))?;
                for e in entries.flatten() {
                    let p = e.path();
                    if p.is_dir() {
                        stack.push(p);
                    } else if p.extension().is_some_and(|x| x.eq_ignore_ascii_case("xosc")) {
                        // a catalog found in a folder is checked through the scenarios that use
                        // it: read alone, the parameters its referrers declare are missing
                        if !matches!(convert::classify(&p), convert::FileKind::Skip(_)) {
                            found.push(p);
                        }
                    }
                }
            }
            found.sort();
            out.extend(found);
        } else if i.is_file() {
            out.push(i.clone());
        } else {
            return Err(Failure::input(format!("{}: no such file or folder", i.display())));
        }
    }
    Ok(out)
}

/// The findings of one file: the schema pass (every problem of the file itself), then the
/// reader's (catalogs, references, the road network), without repeating a line the schema pass
/// already flagged as an error.
fn check_file(path: &Path, params: &[(String, String)]) -> Vec<Finding> {
    let mut out: Vec<Finding> = openscenario::validate::validate_file(path, params)
        .into_iter()
        .map(|f| {
            let severity = match f.severity {
                openscenario::validate::Severity::Error => "error",
                openscenario::validate::Severity::Warning => "warning",
                openscenario::validate::Severity::Info => "info",
            };
            finding(severity, &f.location.file, f.location.line, f.location.col, f.message)
        })
        .collect();
    let schema_errors: Vec<(String, u32, u32)> = out.iter().filter(|f| f.severity == "error").map(|f| (f.file.clone(), f.line, f.column)).collect();
    // The reader's error on a line the schema pass found wrong is the same problem seen again;
    // so is its warning at the very place of a schema error (an unknown attribute is also unread).
    let already = |f: &Finding| schema_errors.iter().any(|(file, line, col)| *file == f.file && *line == f.line && (f.severity == "error" || *col == f.column));
    let reader = reader_findings(path, params);
    out.extend(reader.into_iter().filter(|f| !already(f)));
    convert_stops::hold_to_convert(&mut out, path, params);
    out
}

fn reader_findings(path: &Path, params: &[(String, String)]) -> Vec<Finding> {
    let mut out = Vec::new();
    let options = openscenario::LoadOptions { parameters: params.to_vec(), go_on_without_catalogs: true, ..Default::default() };
    let loaded = match openscenario::load(path, &options) {
        Ok(l) => l,
        Err(e) => {
            let l = &e.location;
            // A catalog that is not there is a gap in what was given, not a fault of this file:
            // the file's own problems are all reported by the schema pass above.
            let severity = if e.kind == openscenario::ErrorKind::MissingCatalog { "warning" } else { "error" };
            let message =
                if severity == "warning" { format!("{} (what this file takes from the catalog is not checked)", e.message) } else { e.message.clone() };
            out.push(finding(severity, &l.file, l.line, l.col, message));
            return out;
        }
    };
    for w in &loaded.warnings {
        let l = &w.location;
        out.push(finding("warning", &l.file, l.line, l.col, w.message.clone()));
    }
    for p in &loaded.problems {
        let l = &p.location;
        out.push(finding("error", &l.file, l.line, l.col, p.message.clone()));
    }
    if let openscenario::Content::Scenario(s) = &loaded.content {
        let road = match &s.road_network.logic_file {
            Some(f) => match opendrive::load(f) {
                Ok(r) => {
                    for w in &r.warnings {
                        out.push(finding("warning", &w.file, w.line, w.col, w.message.clone()));
                    }
                    Some(r.network)
                }
                // the reader has said where the scenario names it; say what follows from it
                Err(_) if !f.exists() => {
                    if let Some(w) = out.iter_mut().find(|w| w.message.starts_with("road network ") && w.message.ends_with(" not found")) {
                        w.message.push_str(" (positions are not checked against a road network)");
                    }
                    None
                }
                Err(e) => {
                    out.push(finding("error", f, 0, 0, e.to_string()));
                    None
                }
            },
            None => None,
        };
        if road.is_some() {
            for p in engine::road_references(s, road.as_ref()) {
                out.push(finding("error", &p.file, p.line, p.col, p.message.clone()));
            }
        }
    }
    out
}

pub(crate) fn run(args: &CheckArgs) -> Result<(), Failure> {
    let files = xosc_files(&args.inputs)?;
    if files.is_empty() {
        return Err(Failure::input("no .xosc file among the inputs"));
    }
    let findings: Vec<Finding> = files.iter().flat_map(|f| check_file(f, &args.params.values)).collect();
    let errors = findings.iter().filter(|f| f.severity == "error").count();
    let warnings = findings.len() - errors;
    if args.json {
        let json = serde_json::to_string_pretty(&findings).map_err(|e| Failure::input(e.to_string()))?;
        println!("{json}");
    } else {
        for f in findings.iter().filter(|f| args.verbose || f.severity == "error") {
            if f.line == 0 {
                println!("{}: {}: {}", f.file, f.severity, f.message);
            } else {
                println!("{}:{}:{}: {}: {}", f.file, f.line, f.column, f.severity, f.message);
            }
        }
        eprintln!(
            "{} file{} checked: {errors} error{}, {warnings} warning{}{}",
            files.len(),
            if files.len() == 1 { "" } else { "s" },
            if errors == 1 { "" } else { "s" },
            if warnings == 1 { "" } else { "s" },
            if args.verbose || warnings == 0 { "" } else { " (-v lists them)" }
        );
    }
    if errors > 0 {
        return Err(Failure { message: format!("{errors} error{} found", if errors == 1 { "" } else { "s" }), status: 2 });
    }
    Ok(())
}

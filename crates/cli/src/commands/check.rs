//! `osc2cr check`: what is wrong with OpenSCENARIO files, without converting them — every file
//! of the inputs (folders are searched) is read as `convert` reads it, its road network loaded
//! and its positions checked against it, and each finding printed with severity and
//! file:line:col. Errors are what stops `convert` (malformed XML or values, a missing catalog
//! entry, a reference to what does not exist); warnings are what it approximates or ignores.

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::failure::Failure;
use crate::shared_options::ParamArgs;

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
    /// Also list warnings (by default only errors and a count of warnings are printed). A finding
    /// repeated in one file is listed once, at its first position, with how many more there
    /// are; `-vv` lists every one (as `--json` does).
    #[arg(short, long, action = clap::ArgAction::Count)]
    pub verbose: u8,
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

fn diagnostic_finding(severity: &'static str, d: &diagnostic::Diagnostic) -> Finding {
    finding(severity, &d.location.file, d.location.line, d.location.col, d.message.clone())
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
    let schema: Vec<(String, u32, u32, bool)> = out.iter().map(|f| (f.file.clone(), f.line, f.column, f.severity == "error")).collect();
    // The reader's error on a line the schema pass found wrong is the same problem seen again;
    // so is any finding of the reader at the very place of one of the schema pass (an unknown
    // attribute is also unread; a catalog's undeclared parameter also stops its entry).
    let already = |f: &Finding| {
        schema.iter().any(|(file, line, col, error)| *file == f.file && *line == f.line && ((*error && f.severity == "error") || *col == f.column))
    };
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
            let message = if severity == "warning" { format!("{} {}", e.message, openscenario::CATALOG_NOT_CHECKED) } else { e.message.clone() };
            out.push(finding(severity, &l.file, l.line, l.col, message));
            return out;
        }
    };
    out.extend(loaded.warnings.iter().map(|w| diagnostic_finding("warning", w)));
    out.extend(loaded.problems.iter().map(|p| diagnostic_finding("error", p)));
    if let openscenario::Content::Scenario(s) = &loaded.content {
        let road = match &s.road_network.logic_file {
            Some(f) => match opendrive::load(f) {
                Ok(r) => {
                    out.extend(r.warnings.iter().map(|w| diagnostic_finding("warning", w)));
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
            out.extend(engine::road_references(s, road.as_ref()).iter().map(|p| diagnostic_finding("error", p)));
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
        let shown: Vec<&Finding> = findings.iter().filter(|f| args.verbose > 0 || f.severity == "error").collect();
        let lines: Vec<(&&Finding, usize)> = if args.verbose > 1 {
            shown.iter().map(|f| (f, 0)).collect()
        } else {
            crate::grouped::by_kind(&shown, |f| (f.file.clone(), f.severity, crate::grouped::kind(&f.message)))
        };
        for (f, more) in lines {
            let more = crate::grouped::more(more);
            if f.line == 0 {
                println!("{}: {}: {}{more}", f.file, f.severity, f.message);
            } else {
                println!("{}:{}:{}: {}: {}{more}", f.file, f.line, f.column, f.severity, f.message);
            }
        }
        eprintln!(
            "{} file{} checked: {errors} error{}, {warnings} warning{}{}",
            files.len(),
            if files.len() == 1 { "" } else { "s" },
            if errors == 1 { "" } else { "s" },
            if warnings == 1 { "" } else { "s" },
            if args.verbose > 0 || warnings == 0 { "" } else { " (-v lists them)" }
        );
    }
    if errors > 0 {
        return Err(Failure { message: format!("{errors} error{} found", if errors == 1 { "" } else { "s" }), status: 2 });
    }
    Ok(())
}

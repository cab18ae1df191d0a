//! What `convert` stops on, held against `check`'s own findings so that the two agree: a file
//! `check` passes converts, and a file `convert` refuses has an error in `check` at the place
//! `convert` names. Each of `convert::preflight::stops` (the reader's strict errors, a catalog
//! or road network that cannot be read, positions on roads the map does not have, positions on
//! roads without a map, …) either is a finding already — an error on its line, or the reader's
//! warning of that very problem, which becomes the error it is for `convert` — or is added as
//! an error. Two stops are not faults of the file, and stay warnings: a catalog in directories
//! that are not there (a gap in what was given: esmini runs the file where the catalog is) and
//! a scenario without entities (valid, run by esmini, only not convertible: no ego, no planning
//! problem).

use std::path::Path;

use super::Finding;

/// Raises or adds to `findings` (those of `path`, checked with the overrides `params`) every
/// problem `convert` stops on.
pub(super) fn hold_to_convert(findings: &mut Vec<Finding>, path: &Path, params: &[(String, String)]) {
    for stop in convert::preflight::stops(path, params) {
        let l = &stop.location;
        let file = l.file.display().to_string();
        // a scenario without entities is valid OpenSCENARIO, and esmini runs it: only the
        // conversion has nothing to write (a CommonRoad file needs a planning problem, hence an
        // ego), so `check` says so without refusing the file
        if stop.message == convert::NO_EGO {
            let message = format!("{} (convert refuses it: a CommonRoad scenario needs a planning problem)", stop.message);
            findings.push(super::finding("warning", &l.file, l.line, l.col, message));
            continue;
        }
        // the reader's warning of this very problem (a catalog it read on without)
        let told = |f: &Finding| f.file == file && f.line == l.line && f.column == l.col && f.message.starts_with(&stop.message);
        if let Some(f) = findings.iter_mut().find(|f| told(f)) {
            // a catalog in directories that are not there is a gap in what was given, not a
            // fault of the file (esmini runs it where the catalog is): it stays the reader's
            // warning, which says what is not checked
            if !f.message.ends_with(openscenario::CATALOG_NOT_CHECKED) {
                f.severity = "error";
            }
            continue;
        }
        // the same problem seen by another pass on the same line (the schema's, the reader's)
        if findings.iter().any(|f| f.file == file && f.line == l.line && f.severity == "error") {
            continue;
        }
        findings.push(super::finding("error", &l.file, l.line, l.col, stop.message));
    }
}

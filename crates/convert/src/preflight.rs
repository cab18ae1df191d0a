//! What stops a conversion before its run, said as its real cause, and shared by the pipeline
//! and `osc2cr check` so that the two agree on what a file may not have.
//!
//! - [`cause`]: why a scenario file cannot be used at all — there is no such file, it is not
//!   well-formed XML, or a `--param` (or a distribution's) value does not fit its parameter's
//!   declared type. The schema pass reports these among its findings; a file that fails for one
//!   of them is announced as what it is, not as "errors against the schema".
//! - [`road_failure`]: the road network a scenario names cannot be read, said at the scenario's
//!   `<LogicFile>`.
//! - [`stops`]: everything the pipeline stops on that can be known without running the
//!   scenario (besides the schema pass, which a checker runs itself), collected instead of
//!   stopping at the first, each positioned: what `osc2cr check` adds to its own findings.

use std::path::Path;

use openscenario::{Content, Diagnostic, ErrorKind, LoadOptions, Location, Scenario};

/// A problem a conversion stops on, where it is.
pub type Stop = Diagnostic;

fn stop(location: Location, message: impl Into<String>) -> Stop {
    Diagnostic::new(location, message)
}

/// Why `path` cannot be used at all, if that is the case: no such file (or a folder, or
/// unreadable), not well-formed XML (at its line and column), or values of `params` (the
/// `--param` overrides) or `variation` (a distribution's values) that do not fit their
/// parameters' declared types. Empty when the file can be read and the values fit.
pub fn cause(path: &Path, params: &[(String, String)], variation: &[(String, String)]) -> Vec<Stop> {
    match std::fs::metadata(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return vec![stop(Location::file_only(path), "no such file")],
        Err(e) => return vec![stop(Location::file_only(path), format!("cannot be read: {e}"))],
        Ok(m) if m.is_dir() => return vec![stop(Location::file_only(path), "is a folder, not an OpenSCENARIO file")],
        Ok(_) => {}
    }
    if let Err(e) = openscenario::load(path, &LoadOptions::default()) {
        if matches!(e.kind, ErrorKind::Xml | ErrorKind::Io | ErrorKind::Limit) {
            return vec![stop(e.location, e.message)];
        }
    }
    let bad = |given: &[(String, String)], what: &str| -> Vec<Stop> {
        openscenario::validate::overrides::bad_overrides(path, given)
            .into_iter()
            .map(|b| {
                let message = format!("{what} {}={}: parameter '{}' is declared {} here, and {}", b.name, b.value, b.name, b.declared, b.why);
                stop(b.location, message)
            })
            .collect()
    };
    let mut out = bad(params, "bad --param value");
    out.extend(bad(variation, "bad value from the parameter distribution,"));
    out
}

/// The failure of reading `xodr`, the road network `scenario` names, said at its
/// `<LogicFile>`: "no such file" when it is not there, else the reader's error.
pub fn road_failure(scenario: &Scenario, xodr: &Path, error: &str) -> Stop {
    let at = scenario.road_network.logic_file_at.clone().unwrap_or_else(|| Location::file_only(&scenario.path));
    if xodr.exists() {
        stop(at, format!("the road network (LogicFile) cannot be read: {error}"))
    } else {
        stop(at, format!("the road network (LogicFile) {}: no such file", xodr.display()))
    }
}

/// Everything a strict conversion of `path` with the overrides `params` stops on before its
/// engine runs, but for the schema pass: the [`cause`]s; else the reader's error, or the
/// references to what does not exist, catalogs and catalog entries that cannot be found (each
/// of them, the reading going on past them) and distributions that cannot be sampled; a road network
/// that cannot be read; positions on roads and lanes the road network does not have (or any
/// road position when the scenario names no road network); a scenario without any entity (its
/// planning problem has no ego). A distribution's scenario file is checked with the
/// distribution's first parameter set.
pub fn stops(path: &Path, params: &[(String, String)]) -> Vec<Stop> {
    stops_with(path, params, &[], 0)
}

fn stops_with(path: &Path, params: &[(String, String)], variation: &[(String, String)], depth: u8) -> Vec<Stop> {
    let found = cause(path, params, variation);
    if !found.is_empty() {
        return found;
    }
    let mut parameters = params.to_vec();
    parameters.extend(variation.iter().cloned());
    // past a missing catalog (what convert stops on) to what follows it
    let loaded = match openscenario::load(path, &LoadOptions { parameters, go_on_without_catalogs: true, ..Default::default() }) {
        Ok(l) => l,
        Err(e) => return vec![stop(e.location, e.message)],
    };
    // a catalog whose directories are not there is a warning of that reading: each reference
    // to it is where a conversion's reading would stop
    let gaps = loaded.warnings.iter().filter_map(|w| {
        let message = w.message.strip_suffix(openscenario::CATALOG_NOT_CHECKED)?;
        Some(stop(w.location.clone(), message.trim_end()))
    });
    let mut out: Vec<Stop> = loaded.problems.iter().cloned().chain(gaps).collect();
    match &loaded.content {
        Content::Scenario(s) => {
            out.extend(road_stops(s));
            // the planning problem starts at the ego: no entity, no conversion
            if s.entities.is_empty() {
                out.push(stop(Location::file_only(path), crate::ego::NO_EGO));
            }
        }
        // a distribution of a distribution is refused by the reader of its scenario file
        Content::Distribution(d) if depth == 0 => {
            let first = d.get(0).unwrap_or_default();
            out.extend(stops_with(&d.scenario_file, params, &first, depth + 1));
        }
        Content::Distribution(_) | Content::Catalog(_) => {}
    }
    out
}

/// The road network of `s` and the road positions it cannot resolve.
fn road_stops(s: &Scenario) -> Vec<Stop> {
    let road = match &s.road_network.logic_file {
        Some(xodr) => match opendrive::load(xodr) {
            Ok(r) => Some(r.network),
            Err(e) => return vec![road_failure(s, xodr, &e.to_string())],
        },
        None => None,
    };
    engine::road_references(s, road.as_ref())
}

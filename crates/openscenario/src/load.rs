//! Entry points: load a file (scenario, parameter distribution or catalog) into the model.

use crate::attr::Record;
use crate::catalog_file::{read_catalog_file, CatalogFile};
use crate::distribution::{read_distribution, Distribution};
use crate::error::{absolute, Diagnostic, Error, ErrorKind, Location};
use crate::model::Scenario;
use crate::read::{read_scenario, Reader};
use crate::xml::{parse_str, read_file, Doc};
use std::path::Path;

/// Options of a load.
#[derive(Debug, Clone, Default)]
pub struct LoadOptions {
    /// Values for global parameters (`--param NAME=VALUE`); they replace the declared values.
    pub parameters: Vec<(String, String)>,
    /// Seed for stochastic distributions; None: the file's `randomSeed` (or 0).
    pub seed: Option<u64>,
    /// Read on past a vehicle, pedestrian, object, controller or maneuver whose catalog or
    /// catalog entry cannot be found, with a placeholder (an external object, no controller,
    /// no maneuver), so that a check reports everything else as well: a catalog whose
    /// directories are not all there is then a warning (a conversion stops on it all the same),
    /// any other missing catalog or entry a problem ([`Loaded::problems`]). Never for a
    /// conversion.
    pub go_on_without_catalogs: bool,
}

/// How a reading past a missing catalog ([`LoadOptions::go_on_without_catalogs`]) ends the
/// warning about a catalog whose directories are not there: what the file takes from it is not
/// checked (and a conversion, which never reads past it, stops there).
pub const CATALOG_NOT_CHECKED: &str = "(what this file takes from the catalog is not checked)";

/// What a file turned out to be.
#[derive(Debug, Clone)]
pub enum Content {
    Scenario(Box<Scenario>),
    Distribution(Distribution),
    Catalog(CatalogFile),
}

/// A loaded file with the warnings collected while reading it.
#[derive(Debug, Clone)]
pub struct Loaded {
    pub content: Content,
    pub warnings: Vec<Diagnostic>,
    /// What a strict reading rejects: names that refer to nothing the scenario declares
    /// (entities, storyboard elements, parameters, variables — see [`crate::references`]),
    /// parameter overrides the scenario does not declare, distributions that cannot be sampled.
    /// The file was read as if they were absent; the caller decides whether they stop it
    /// (osc2cr's default) or are reported as warnings (`--lenient`).
    pub problems: Vec<Diagnostic>,
}

/// Loads an OpenSCENARIO file: a scenario (parameters and catalogs resolved), a
/// ParameterValueDistribution (its scenario is not loaded), or a catalog.
pub fn load(path: &Path, options: &LoadOptions) -> Result<Loaded, Error> {
    let doc = read_file(path)?;
    load_doc(path, doc, options)
}

/// Like [`load`] with the text given; `path` names the file in messages and anchors relative paths.
pub fn load_str(path: &Path, text: &str, options: &LoadOptions) -> Result<Loaded, Error> {
    let doc = parse_str(path, text)?;
    load_doc(path, doc, options)
}

/// Loads a file that must be a scenario, leniently: its [`Loaded::problems`] are returned among
/// the warnings (use [`load`] to treat them as errors).
pub fn load_scenario(path: &Path, options: &LoadOptions) -> Result<(Scenario, Vec<Diagnostic>), Error> {
    let loaded = load(path, options)?;
    let mut warnings = loaded.warnings;
    warnings.extend(loaded.problems);
    match loaded.content {
        Content::Scenario(s) => Ok((*s, warnings)),
        _ => Err(Error::new(
            ErrorKind::Structure,
            Location::file_only(path),
            "expected a scenario (OpenSCENARIO with a Storyboard), found a distribution or catalog file",
        )),
    }
}

fn load_doc(path: &Path, doc: Doc, options: &LoadOptions) -> Result<Loaded, Error> {
    let abs = absolute(path);
    let root = &doc.root;
    if root.name != "OpenSCENARIO" {
        return Err(Error::new(
            ErrorKind::Structure,
            Location { file: doc.file.clone(), line: root.pos.line, col: root.pos.col },
            format!("expected root element <OpenSCENARIO>, found <{}>", root.name),
        ));
    }
    let mut reader = Reader::new();
    reader.go_on_without_catalogs = options.go_on_without_catalogs;
    let record = Record::default();
    let content = if root.child("Storyboard").is_some() {
        let mut scenario = read_scenario(&mut reader, &record, &abs, &doc.file, root, &options.parameters)?;
        scenario.reference_sites = record.sites.take();
        reader.problems.append(&mut record.problems.take());
        reader.problems.extend(crate::references::unresolved(&scenario));
        reader.warnings.extend(crate::references::ambiguous(&scenario));
        Content::Scenario(Box::new(scenario))
    } else if let Some(d) = root.child("ParameterValueDistribution") {
        Content::Distribution(read_distribution(&mut reader.warnings, &mut reader.problems, &abs, &doc.file, root, d, options.seed)?)
    } else if let Some(c) = root.child("Catalog") {
        let catalog = read_catalog_file(&mut reader, &record, &doc.file, c)?;
        reader.problems.append(&mut record.problems.take());
        Content::Catalog(catalog)
    } else {
        return Err(Error::new(
            ErrorKind::Structure,
            Location { file: doc.file.clone(), line: root.pos.line, col: root.pos.col },
            "expected a Storyboard (scenario), a ParameterValueDistribution or a Catalog in <OpenSCENARIO>",
        ));
    };
    // What the reader never asked for is ignored: say so (`unread.rs`).
    reader.warnings.extend(crate::unread::report_document(&doc));
    for catalog in reader.catalogs.documents() {
        reader.warnings.extend(crate::unread::report_catalog(catalog));
    }
    Ok(Loaded { content, warnings: reader.warnings, problems: reader.problems })
}

//! Finding the scenarios of a batch: files are taken as given, folders are searched (sorted,
//! depth-limited: `batch_inputs`) for `.xosc` files, and each file is classified by its root element —
//! scenario (has a Storyboard), parameter distribution, or something to skip (catalog, no
//! storyboard), so that a skipped file can be reported with its reason.

use std::path::{Path, PathBuf};

use batch_inputs::MAX_FILES;

/// Files larger than this are not peeked at; the loader reports them.
const MAX_PEEK_BYTES: u64 = 64 << 20;

/// What a file is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FileKind {
    Scenario,
    Distribution,
    /// Not converted, with the reason.
    Skip(String),
}

/// A file of the batch.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Found {
    pub path: PathBuf,
    /// Summary group: the folder searched plus the file's sub-folder (or the file's folder).
    pub folder: String,
    /// Output path relative to the output directory, without extension: the sub-folder under
    /// the folder searched and the file stem (just the stem for a file given directly).
    pub output_stem: PathBuf,
    pub kind: FileKind,
}

/// The files of `inputs`, in argument order, each folder's files sorted by path.
pub fn discover(inputs: &[PathBuf]) -> Result<Vec<Found>, String> {
    let is_xosc = |p: &Path| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("xosc"));
    let mut out = Vec::new();
    for input in inputs {
        for g in batch_inputs::files_of(input, &is_xosc, ".xosc files")? {
            let kind = classify(&g.path);
            out.push(Found { output_stem: g.sub.join(stem(&g.path)), path: g.path, folder: g.folder, kind });
        }
        if out.len() > MAX_FILES {
            return Err(format!("more than {MAX_FILES} files to convert"));
        }
    }
    Ok(out)
}

fn stem(path: &Path) -> String {
    path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "scenario".into())
}

/// Classifies a file by the children of its `<OpenSCENARIO>` root. A file that cannot be read
/// or parsed is classified as a scenario, so that the loader reports the precise error.
pub fn classify(path: &Path) -> FileKind {
    let too_big = std::fs::metadata(path).map_or(true, |m| m.len() > MAX_PEEK_BYTES);
    if too_big {
        return FileKind::Scenario;
    }
    let Ok(text) = std::fs::read_to_string(path) else {
        return FileKind::Scenario;
    };
    let Ok(doc) = roxmltree::Document::parse(&text) else {
        return FileKind::Scenario;
    };
    let root = doc.root_element();
    if root.tag_name().name() != "OpenSCENARIO" {
        return FileKind::Skip(format!("not an OpenSCENARIO file (root element <{}>)", root.tag_name().name()));
    }
    let has = |name: &str| root.children().any(|c| c.tag_name().name() == name);
    if has("Storyboard") {
        FileKind::Scenario
    } else if has("ParameterValueDistribution") {
        FileKind::Distribution
    } else if has("Catalog") {
        FileKind::Skip("catalog file".into())
    } else {
        FileKind::Skip("no Storyboard (not a scenario)".into())
    }
}

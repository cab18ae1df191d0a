//! Finding the scenarios of a batch: files are taken as given, folders are searched (sorted,
//! depth-limited) for `.xosc` files, and each file is classified by its root element —
//! scenario (has a Storyboard), parameter distribution, or something to skip (catalog, no
//! storyboard), so that a skipped file can be reported with its reason.

use std::path::{Path, PathBuf};

/// How deep folders are searched (also stops symbolic-link cycles).
const MAX_DEPTH: usize = 32;
/// Most files one batch may name.
const MAX_FILES: usize = 100_000;
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
    let mut out = Vec::new();
    for input in inputs {
        if input.is_dir() {
            let mut files = Vec::new();
            walk(input, 0, &mut files)?;
            files.sort();
            let base = label(input);
            for f in files {
                let rel = f.strip_prefix(input).unwrap_or(&f).to_path_buf();
                let sub = rel.parent().unwrap_or(Path::new("")).to_path_buf();
                let folder = if sub.as_os_str().is_empty() { base.clone() } else { format!("{base}/{}", sub.display()) };
                let kind = classify(&f);
                out.push(Found { output_stem: sub.join(stem(&f)), path: f, folder, kind });
            }
        } else if input.is_file() {
            let folder = input.parent().map_or_else(|| ".".into(), label);
            out.push(Found { output_stem: PathBuf::from(stem(input)), path: input.clone(), folder, kind: classify(input) });
        } else {
            return Err(format!("{}: no such file or directory", input.display()));
        }
        if out.len() > MAX_FILES {
            return Err(format!("more than {MAX_FILES} files to convert"));
        }
    }
    Ok(out)
}

/// A folder's name in the summary table: its last component, or the path itself (`..`); the
/// current folder (a file given without one) is `.`, never an empty cell.
fn label(dir: &Path) -> String {
    match dir.file_name() {
        Some(n) => n.to_string_lossy().into_owned(),
        None if dir.as_os_str().is_empty() => ".".into(),
        None => dir.display().to_string(),
    }
}

fn stem(path: &Path) -> String {
    path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_else(|| "scenario".into())
}

fn walk(dir: &Path, depth: usize, out: &mut Vec<PathBuf>) -> Result<(), String> {
    if depth > MAX_DEPTH {
        return Ok(());
    }
    let entries = std::fs::read_dir(dir).map_err(|e| format!("cannot read folder {}: {e}", dir.display()))?;
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            walk(&path, depth + 1, out)?;
        } else if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("xosc")) {
            out.push(path);
            if out.len() > MAX_FILES {
                return Err(format!("more than {MAX_FILES} .xosc files under {}", dir.display()));
            }
        }
    }
    Ok(())
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

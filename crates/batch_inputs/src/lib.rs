//! `batch_inputs`: the files a batch is given, for `osc2cr convert` (OpenSCENARIO files) and
//! `osc2cr export` (CommonRoad files) alike. A file is taken as named; a folder is searched
//! depth-first (at most 32 levels deep, which also stops symbolic-link cycles) for the files
//! the caller wants, sorted by path, and each keeps its sub-folder under the folder searched
//! (where its output goes) and its group in the summary table (the folder's name and that
//! sub-folder). What a file is, what is skipped and how outputs are named stay the callers'.
//!
//! ```
//! let dir = std::env::temp_dir().join(format!("batch-inputs-doc-{}", std::process::id()));
//! std::fs::create_dir_all(dir.join("sub")).unwrap();
//! std::fs::write(dir.join("sub/b.xosc"), "").unwrap();
//! std::fs::write(dir.join("a.xosc"), "").unwrap();
//! std::fs::write(dir.join("notes.txt"), "").unwrap();
//! let is_xosc = |p: &std::path::Path| p.extension().is_some_and(|e| e == "xosc");
//! let files = batch_inputs::files_of(&dir, &is_xosc, ".xosc files").unwrap();
//! let name = dir.file_name().unwrap().to_string_lossy().into_owned();
//! assert_eq!(files[0].path, dir.join("a.xosc"));
//! assert_eq!((files[0].folder.clone(), files[0].sub.clone()), (name.clone(), "".into()));
//! assert_eq!((files[1].folder.clone(), files[1].sub.clone()), (format!("{name}/sub"), "sub".into()));
//! assert_eq!(files.len(), 2);
//! std::fs::remove_dir_all(&dir).unwrap();
//! ```

// A library returns its errors as data and never prints (ARCHITECTURE.md, Invariants).
#![cfg_attr(not(test), deny(clippy::print_stdout, clippy::print_stderr))]

use std::path::{Path, PathBuf};

/// How deep folders are searched (also stops symbolic-link cycles).
pub const MAX_DEPTH: usize = 32;
/// Most files one batch may name.
pub const MAX_FILES: usize = 100_000;

/// A file of a batch.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Given {
    pub path: PathBuf,
    /// Summary group: the folder searched plus the file's sub-folder (or the file's folder).
    pub folder: String,
    /// The file's folder under the folder searched (empty for a file named directly).
    pub sub: PathBuf,
}

/// The files of one input: the file itself, or a folder's files that `wanted` takes, sorted by
/// path. `what` names them in the message of the cap on a folder ("`.xosc` files").
pub fn files_of(input: &Path, wanted: &dyn Fn(&Path) -> bool, what: &str) -> Result<Vec<Given>, String> {
    if input.is_dir() {
        let mut files = Vec::new();
        walk(input, 0, wanted, what, &mut files)?;
        files.sort();
        let base = label(input);
        Ok(files
            .into_iter()
            .map(|f| {
                let rel = f.strip_prefix(input).unwrap_or(&f).to_path_buf();
                let sub = rel.parent().unwrap_or(Path::new("")).to_path_buf();
                let folder = if sub.as_os_str().is_empty() { base.clone() } else { format!("{base}/{}", sub.display()) };
                Given { path: f, folder, sub }
            })
            .collect())
    } else if input.is_file() {
        let folder = input.parent().map_or_else(|| ".".into(), label);
        Ok(vec![Given { path: input.to_path_buf(), folder, sub: PathBuf::new() }])
    } else {
        Err(format!("{}: no such file or directory", input.display()))
    }
}

/// A folder's name in the summary table: its last component, or the path itself (`..`); the
/// current folder (a file named without one) is `.`, never an empty cell.
pub fn label(dir: &Path) -> String {
    match dir.file_name() {
        Some(n) => n.to_string_lossy().into_owned(),
        None if dir.as_os_str().is_empty() => ".".into(),
        None => dir.display().to_string(),
    }
}

fn walk(dir: &Path, depth: usize, wanted: &dyn Fn(&Path) -> bool, what: &str, out: &mut Vec<PathBuf>) -> Result<(), String> {
    if depth > MAX_DEPTH {
        return Ok(());
    }
    let entries = std::fs::read_dir(dir).map_err(|e| format!("cannot read folder {}: {e}", dir.display()))?;
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            walk(&path, depth + 1, wanted, what, out)?;
        } else if wanted(&path) {
            out.push(path);
            if out.len() > MAX_FILES {
                return Err(format!("more than {MAX_FILES} {what} under {}", dir.display()));
            }
        }
    }
    Ok(())
}

// The README's example is compiled with the doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;

//! Shared helpers for integration tests: locating the corpus.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// `../shared` (or $OSC2CR_SHARED). None (after a notice) when absent outside CI.
pub fn shared_dir() -> Option<PathBuf> {
    let dir = std::env::var_os("OSC2CR_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    if dir.is_dir() {
        return Some(dir);
    }
    if std::env::var_os("CI").is_some() {
        panic!("corpus directory {} missing and CI is set", dir.display());
    }
    eprintln!("notice: {} not found; corpus test skipped", dir.display());
    None
}

/// All corpus .xodr files, sorted.
pub fn corpus_xodr() -> Option<Vec<PathBuf>> {
    let root = shared_dir()?.join("corpus");
    let mut out = Vec::new();
    let mut stack = vec![root];
    while let Some(d) = stack.pop() {
        let Ok(rd) = std::fs::read_dir(&d) else { continue };
        for e in rd.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|x| x == "xodr") {
                out.push(p);
            }
        }
    }
    out.sort();
    Some(out)
}

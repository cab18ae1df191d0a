//! Collects warnings: single ones with their source position, and repeated kinds (e.g. a
//! skipped lane type) counted and reported once, at their first occurrence.

use diagnostic::{Diagnostic, LineCol, Location};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

#[derive(Debug, Default)]
pub struct WarningSink {
    single: Vec<Diagnostic>,
    /// message → (count, file, first position)
    counted: BTreeMap<String, (usize, PathBuf, LineCol)>,
}

impl WarningSink {
    /// A warning at a source position.
    pub fn at(&mut self, file: &Path, pos: LineCol, message: String) {
        self.single.push(Diagnostic::new(Location::new(file, pos.line, pos.col), message));
    }

    /// One more occurrence of a counted kind.
    pub fn count(&mut self, what: &str, file: &Path, pos: LineCol) {
        self.counted.entry(what.to_string()).or_insert_with(|| (0, file.to_path_buf(), pos)).0 += 1;
    }

    /// All warnings: the single ones in order, then one per counted kind.
    pub fn finish(self) -> Vec<Diagnostic> {
        let mut out = self.single;
        for (what, (n, file, pos)) in self.counted {
            out.push(Diagnostic::new(Location::new(file, pos.line, pos.col), format!("{n} {what} (first here)")));
        }
        out
    }
}

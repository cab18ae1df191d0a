//! Collects warnings: single ones with their source position, and repeated kinds (e.g. a
//! skipped lane type) counted and reported once, at their first occurrence.

use opendrive::{SourcePos, Warning};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

#[derive(Debug, Default)]
pub struct WarningSink {
    single: Vec<Warning>,
    /// message → (count, file, first position)
    counted: BTreeMap<String, (usize, PathBuf, SourcePos)>,
}

impl WarningSink {
    /// A warning at a source position.
    pub fn at(&mut self, file: &Path, pos: SourcePos, message: String) {
        self.single.push(Warning { file: file.to_path_buf(), line: pos.line, col: pos.col, message });
    }

    /// One more occurrence of a counted kind.
    pub fn count(&mut self, what: &str, file: &Path, pos: SourcePos) {
        self.counted.entry(what.to_string()).or_insert_with(|| (0, file.to_path_buf(), pos)).0 += 1;
    }

    /// All warnings: the single ones in order, then one per counted kind.
    pub fn finish(self) -> Vec<Warning> {
        let mut out = self.single;
        for (what, (n, file, pos)) in self.counted {
            out.push(Warning { file, line: pos.line, col: pos.col, message: format!("{n} {what} (first here)") });
        }
        out
    }
}

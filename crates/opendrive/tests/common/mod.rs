//! Shared helpers for integration tests: locating the corpus.
#![allow(dead_code)]

use std::path::PathBuf;

pub(crate) use testkit::shared_dir;

/// All corpus .xodr files, sorted.
pub(crate) fn corpus_xodr() -> Option<Vec<PathBuf>> {
    Some(testkit::files_with_ext(&shared_dir()?.join("corpus"), "xodr"))
}

//! A named pipe with a reader, to test that an output written to a device or pipe (`--csv
//! /dev/null`) is written in place — without risking `/dev/null` itself when the code under test
//! is wrong.

use std::path::{Path, PathBuf};
use std::thread::JoinHandle;

/// A FIFO at a path and the thread that reads everything written into it.
pub struct Fifo {
    path: PathBuf,
    reader: JoinHandle<Vec<u8>>,
}

impl Fifo {
    /// Makes a FIFO at `path` (with `mkfifo`) and starts reading it; `None` (with a notice) where
    /// `mkfifo` is not available.
    pub fn new(path: &Path) -> Option<Fifo> {
        let made = std::process::Command::new("mkfifo").arg(path).status();
        if !made.is_ok_and(|s| s.success()) {
            // testkit serves tests: a skipped test's notice to whoever runs them is its one output
            #[allow(clippy::print_stderr)]
            {
                eprintln!("notice: mkfifo is not available; skipping this test");
            }
            return None;
        }
        let p = path.to_path_buf();
        let reader = std::thread::spawn(move || std::fs::read(&p).unwrap_or_default());
        Some(Fifo { path: path.to_path_buf(), reader })
    }

    /// What was written (the writer must have closed it), after asserting that the path is still
    /// a FIFO — not replaced by a regular file.
    pub fn received(self) -> Vec<u8> {
        use std::os::unix::fs::FileTypeExt;
        let bytes = self.reader.join().unwrap_or_default();
        let kind = std::fs::symlink_metadata(&self.path).map(|m| m.file_type());
        assert!(kind.is_ok_and(|k| k.is_fifo()), "{} is no longer a pipe", self.path.display());
        bytes
    }
}

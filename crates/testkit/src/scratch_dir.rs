//! A test's scratch directory that goes away with the test.
//!
//! Tests that wrote into `std::env::temp_dir()` under their process id left every run's files
//! behind: the Python package tests alone left a 440 MB virtual environment per run. A
//! `ScratchDir` is removed when dropped — unless the test is panicking, so that a failing test's
//! files stay for a look (its message names the path).

use std::ffi::OsStr;
use std::ops::Deref;
use std::path::{Path, PathBuf};

/// A fresh, empty directory `osc2cr-<tag>-<pid>` under the system temp dir, removed on drop
/// when the test passed.
#[derive(Debug)]
pub struct ScratchDir(PathBuf);

impl ScratchDir {
    /// Creates (after clearing any leftover of the same name) the directory for `tag`.
    pub fn new(tag: &str) -> ScratchDir {
        let d = std::env::temp_dir().join(format!("osc2cr-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap_or_else(|e| panic!("cannot create {}: {e}", d.display()));
        ScratchDir(d)
    }

    /// The directory.
    pub fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for ScratchDir {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

impl Deref for ScratchDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for ScratchDir {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<OsStr> for ScratchDir {
    fn as_ref(&self) -> &OsStr {
        self.0.as_os_str()
    }
}

#[cfg(test)]
mod tests {
    use super::ScratchDir;

    #[test]
    fn the_directory_exists_while_held_and_is_gone_after() {
        let d = ScratchDir::new("testkit-scratch-self-test");
        std::fs::write(d.join("f.txt"), "x").expect("write");
        let p = d.path().to_path_buf();
        assert!(p.join("f.txt").is_file());
        drop(d);
        assert!(!p.exists(), "{} was left behind", p.display());
    }
}

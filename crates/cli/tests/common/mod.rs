//! What the `osc2cr convert` tests share: running the binary, fresh temporary folders, the
//! shipped example (tests only).
#![allow(dead_code)]

pub(crate) mod checker_suite_valid;
pub(crate) mod png;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the built `osc2cr` with `args`.
pub(crate) fn osc2cr(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_osc2cr")).args(args).output().expect("osc2cr runs")
}

/// An empty folder `<target tmp>/<suite>/<name>`, made afresh.
pub(crate) fn tmp(suite: &str, name: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(suite).join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// The scenario the repository ships.
pub(crate) fn example() -> PathBuf {
    testkit::workspace_root().join("examples/cut_in.xosc")
}

/// A path as the `&str` an argument list wants.
pub(crate) fn s(p: &Path) -> &str {
    p.to_str().expect("utf-8 path")
}

/// Asserts that a run of the binary succeeded, showing what it said if not.
pub(crate) fn assert_ok(o: &Output) {
    assert!(o.status.success(), "status {:?}: {}", o.status, String::from_utf8_lossy(&o.stderr));
}

/// Every file below `dir`, relative, sorted.
pub(crate) fn files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).expect("read dir").flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.push(p.strip_prefix(dir).expect("under dir").to_path_buf());
            }
        }
    }
    out.sort();
    out
}

/// Every file below `dir`: relative path → bytes.
pub(crate) fn contents(dir: &Path) -> std::collections::BTreeMap<PathBuf, Vec<u8>> {
    files(dir)
        .into_iter()
        .map(|rel| {
            let bytes = std::fs::read(dir.join(&rel)).expect("read file");
            (rel, bytes)
        })
        .collect()
}

//! Rules of the workspace's own layout. Every crate's tests are one binary (`autotests = false`,
//! `tests/tests.rs` declaring modules), so a test file no `mod` line reaches would never be
//! compiled and its tests would silently stop running: every `.rs` file under a crate's `tests/`
//! must be reachable from the crate's test targets. A target built without its unit-test
//! harness (`test = false`, which spares CI a compile) must have no unit tests to lose.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut BTreeSet<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.insert(p);
        }
    }
}

/// The module names a file declares with `mod name;` (not inline `mod name { … }`).
fn declared_modules(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| {
            let l = l.trim();
            let l = l.strip_prefix("pub(crate) ").or_else(|| l.strip_prefix("pub ")).unwrap_or(l);
            let name = l.strip_prefix("mod ")?.strip_suffix(';')?;
            name.chars().all(|c| c.is_alphanumeric() || c == '_').then(|| name.to_string())
        })
        .collect()
}

/// The files reachable from a test target's root through `mod` declarations.
fn reachable(root: &Path, out: &mut BTreeSet<PathBuf>) {
    if !out.insert(root.to_path_buf()) {
        return;
    }
    let Ok(text) = std::fs::read_to_string(root) else { return };
    let parent = root.parent().unwrap_or(Path::new("."));
    let stem = root.file_stem().and_then(|s| s.to_str()).unwrap_or_default();
    // a root or `mod.rs` declares its siblings; `name.rs` declares files in `name/`
    let dir = if ["tests", "mod", "main"].contains(&stem) { parent.to_path_buf() } else { parent.join(stem) };
    for m in declared_modules(&text) {
        for candidate in [dir.join(format!("{m}.rs")), dir.join(&m).join("mod.rs")] {
            if candidate.is_file() {
                reachable(&candidate, out);
            }
        }
    }
}

/// The roots of a crate's test targets: `[[test]]` paths, and with automatic discovery
/// `tests/*.rs` and `tests/*/main.rs`.
fn test_roots(krate: &Path) -> Vec<PathBuf> {
    let manifest = std::fs::read_to_string(krate.join("Cargo.toml")).unwrap_or_default();
    let mut roots: Vec<PathBuf> = manifest
        .lines()
        .filter_map(|l| l.trim().strip_prefix("path = \"")?.strip_suffix('"').map(|p| krate.join(p)))
        .filter(|p| p.starts_with(krate.join("tests")))
        .collect();
    if !manifest.lines().any(|l| l.trim() == "autotests = false") {
        for e in std::fs::read_dir(krate.join("tests")).into_iter().flatten().flatten() {
            let p = e.path();
            if p.extension().is_some_and(|x| x == "rs") {
                roots.push(p);
            } else if p.join("main.rs").is_file() {
                roots.push(p.join("main.rs"));
            }
        }
    }
    roots
}

/// The workspace's crate folders.
fn crate_dirs() -> Vec<PathBuf> {
    let crates = testkit::workspace_root().join("crates");
    std::fs::read_dir(&crates).expect("crates/").flatten().map(|e| e.path()).collect()
}

#[test]
fn every_test_file_is_compiled_into_a_test_binary() {
    let mut checked = 0;
    for krate in crate_dirs() {
        let mut files = BTreeSet::new();
        rust_files(&krate.join("tests"), &mut files);
        if files.is_empty() {
            continue;
        }
        let mut seen = BTreeSet::new();
        for root in test_roots(&krate) {
            reachable(&root, &mut seen);
        }
        let lost: Vec<_> = files.difference(&seen).collect();
        assert!(lost.is_empty(), "{}: test files no `mod` declaration reaches (declare them in tests/tests.rs or a mod.rs): {lost:?}", krate.display());
        checked += files.len();
    }
    // the engine alone has more than 50 test files: the walk found the tree
    assert!(checked > 100, "{checked} test files checked");
}

#[test]
fn a_target_without_a_test_harness_has_no_unit_tests() {
    let mut checked = 0;
    for krate in crate_dirs() {
        let manifest = std::fs::read_to_string(krate.join("Cargo.toml")).unwrap_or_default();
        if !manifest.lines().any(|l| l.trim() == "test = false") {
            continue;
        }
        let mut files = BTreeSet::new();
        rust_files(&krate.join("src"), &mut files);
        let with_tests: Vec<_> =
            files.iter().filter(|f| std::fs::read_to_string(f).is_ok_and(|t| t.contains("#[test]") || t.contains("#[cfg(test)]"))).collect();
        assert!(
            with_tests.is_empty(),
            "{}: `test = false` in Cargo.toml, but these files have unit tests that would never run: {with_tests:?}",
            krate.display()
        );
        checked += 1;
    }
    // the seven libraries without unit tests, and the Python module
    assert!(checked >= 8, "{checked} crates checked");
}

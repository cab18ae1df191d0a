//! Where the shared data lives.

use std::path::{Path, PathBuf};

/// The workspace root (two levels above this crate), canonicalised: Python derives its venv
/// from the interpreter's path *lexically*, so `…/crates/testkit/../../target/py/cr/bin/python`
/// would miss the venv when a directory on the way is a symlink.
pub fn workspace_root() -> PathBuf {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    std::fs::canonicalize(&p).unwrap_or(p)
}

/// The shared directory: `$OSC2CR_SHARED`, else `<workspace>/../shared`.
///
/// Missing: panics when the environment variable `CI` is set (a CI run must not silently
/// skip), otherwise prints a notice on stderr and returns `None` so the test can return early.
pub fn shared_dir() -> Option<PathBuf> {
    let dir = match std::env::var_os("OSC2CR_SHARED") {
        Some(d) => PathBuf::from(d),
        None => workspace_root().join("../shared"),
    };
    if dir.is_dir() {
        return Some(std::fs::canonicalize(&dir).unwrap_or(dir));
    }
    if std::env::var_os("CI").is_some() {
        panic!(
            "shared directory {} not found (CI is set, so tests that need it fail): \
             set OSC2CR_SHARED to the directory holding corpus/ and tools/",
            dir.display()
        );
    }
    // testkit serves tests: a skipped test's notice to whoever runs them is its one output
    #[allow(clippy::print_stderr)]
    {
        eprintln!("notice: shared directory {} not found; skipping this test (set OSC2CR_SHARED)", dir.display());
    }
    None
}

/// Every file under `<shared>/corpus` whose extension is `ext` (case-insensitive, without
/// the dot), sorted; empty when the shared directory is missing.
pub fn corpus_files(ext: &str) -> Vec<PathBuf> {
    match shared_dir() {
        Some(shared) => files_with_ext(&shared.join("corpus"), ext),
        None => Vec::new(),
    }
}

/// Every file below `dir` (recursively) whose extension is `ext` (case-insensitive, without
/// the dot), sorted; unreadable directories are passed over.
pub fn files_with_ext(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e.eq_ignore_ascii_case(ext)) {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The corpus scenarios the reference compares (its JSON beside the trace gives the class
/// `core` or `controller-model`), under `shared`'s corpus, sorted.
pub fn compared_scenarios(shared: &Path) -> Vec<PathBuf> {
    let corpus = shared.join("corpus");
    let reference = shared.join("reference/esmini-3.6.0");
    files_with_ext(&corpus, "xosc")
        .into_iter()
        .filter(|f| {
            let Ok(rel) = f.strip_prefix(&corpus) else { return false };
            let Ok(text) = std::fs::read_to_string(reference.join(rel.with_extension("json"))) else { return false };
            let Ok(json) = serde_json::from_str::<serde_json::Value>(&text) else { return false };
            matches!(json["class"].as_str(), Some("core" | "controller-model"))
        })
        .collect()
}

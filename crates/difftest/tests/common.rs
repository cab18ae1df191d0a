//! What the tests share: a clean folder under the target directory, the built-in maps.

use difftest::generate::maps::{builtin, MapChoice};

/// An empty folder `name` under the tests' temporary directory.
pub(crate) fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("difftest").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("dir");
    d
}

/// The built-in maps, written into a fresh folder `name`.
pub(crate) fn maps(name: &str) -> (std::path::PathBuf, Vec<MapChoice>) {
    let dir = tmp(name);
    let maps = builtin(&dir).expect("maps");
    (dir, maps)
}

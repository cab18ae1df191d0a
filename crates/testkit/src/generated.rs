//! Checked-in generated code held to its generator: the `.rs` files a generator wrote into a
//! fresh folder must be the checked-in ones, byte for byte; with `OSC2CR_BLESS` set, the
//! checked-in ones are rewritten first. Used by the tests that regenerate the prost types.

use std::path::Path;

/// The `.rs` files of `dir`, by name, sorted.
pub fn rs_files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "rs"))
        .map(|p| (p.file_name().unwrap_or_default().to_string_lossy().into_owned(), std::fs::read(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))))
        .collect();
    v.sort();
    v
}

/// Asserts that `checked_in` holds exactly the `.rs` files of `fresh` (rewriting them first when
/// `OSC2CR_BLESS` is set); the names of the files compared.
pub fn assert_generated(fresh: &Path, checked_in: &Path) -> Vec<String> {
    if std::env::var_os("OSC2CR_BLESS").is_some() {
        for (name, bytes) in rs_files(fresh) {
            std::fs::write(checked_in.join(&name), bytes).unwrap_or_else(|e| panic!("bless {name}: {e}"));
        }
    }
    let (want, have) = (rs_files(fresh), rs_files(checked_in));
    let names = |v: &[(String, Vec<u8>)]| v.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(&have), names(&want), "generated files (OSC2CR_BLESS=1 regenerates them)");
    for ((name, a), (_, b)) in want.iter().zip(&have) {
        assert!(a == b, "{}/{name} is not the generator's output (OSC2CR_BLESS=1 regenerates it)", checked_in.display());
    }
    names(&want)
}

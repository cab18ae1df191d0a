//! Every crate of the workspace packs for crates.io (`cargo package --workspace`): names,
//! metadata, versioned dependencies between the crates, and no file a crate needs outside its
//! own folder. The packages are not compiled again here (`--no-verify`): that full check takes
//! minutes and is run by hand before a release (the README says how).

use std::process::Command;

#[test]
fn every_crate_packs() {
    let root = testkit::workspace_root();
    let target = root.join("target/package-check");
    let _ = std::fs::remove_dir_all(target.join("package"));
    let out = Command::new(env!("CARGO"))
        .args(["package", "--workspace", "--no-verify", "--allow-dirty", "--quiet", "--target-dir"])
        .arg(&target)
        .current_dir(&root)
        .output()
        .expect("cargo runs");
    assert!(out.status.success(), "cargo package --workspace:\n{}", String::from_utf8_lossy(&out.stderr));
    let packed: Vec<String> = std::fs::read_dir(target.join("package"))
        .expect("packages written")
        .flatten()
        .filter_map(|e| e.file_name().into_string().ok())
        .filter(|n| n.ends_with(".crate"))
        .collect();
    // every published crate carries the project's prefix (no generic names such as `engine`)
    for name in
        ["osc2cr-0.1.0.crate", "osc2cr-engine-0.1.0.crate", "osc2cr-openscenario-0.1.0.crate", "osc2cr-opendrive-0.1.0.crate", "osc2cr-convert-0.1.0.crate"]
    {
        assert!(packed.iter().any(|p| p == name), "{name} not among {packed:?}");
    }
    assert!(packed.iter().all(|p| p.starts_with("osc2cr")), "{packed:?}");
}

//! The Rust types of the CommonRoad 2024 messages (`src/protobuf/generated/*.rs`) are exactly
//! what prost-build makes of the descriptor set `proto/commonroad_2024.binpb` (extracted from the
//! commonroad-io 2026.1 wheel, see `proto/README.md`): they are regenerated here and compared
//! byte for byte, so the checked-in code cannot drift from the definitions. After a change of the
//! descriptor set, `OSC2CR_BLESS=1 cargo test -p osc2cr-commonroad --test tests protobuf::generated`
//! rewrites them.

use std::path::{Path, PathBuf};

use prost::Message;

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// prost-build's output for the descriptor set, written into `out` (one file per package).
fn generate(out: &Path) {
    let bytes = std::fs::read(crate_dir().join("proto/commonroad_2024.binpb")).expect("descriptor set");
    let fds = prost_types::FileDescriptorSet::decode(bytes.as_slice()).expect("a FileDescriptorSet");
    std::fs::create_dir_all(out).expect("output folder");
    prost_build::Config::new()
        .out_dir(out)
        // no map field is written, but if one ever is, its entries must come out in a fixed order
        .btree_map(["."])
        .compile_fds(fds)
        .expect("prost-build generates the types");
}

#[test]
fn the_checked_in_types_are_prost_builds_output_for_the_descriptor_set() {
    let fresh = std::env::temp_dir().join(format!("osc2cr-protobuf-gen-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&fresh);
    generate(&fresh);
    let names = testkit::assert_generated(&fresh, &crate_dir().join("src/protobuf/generated"));
    // the four packages of the three files and their imports
    assert_eq!(names, ["commonroad_common.rs", "commonroad_dynamic.rs", "commonroad_map.rs", "commonroad_scenario.rs"]);
    let _ = std::fs::remove_dir_all(&fresh);
}

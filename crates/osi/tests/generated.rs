//! The Rust types of the OSI messages (`src/generated/osi3.rs`) are exactly what prost-build
//! makes of `proto/osi3.proto` (our subset of OSI 3.5.0), compiled into a descriptor set by protox
//! (a protobuf compiler in Rust: no `protoc` needed): they are regenerated here and compared byte
//! for byte, so the checked-in code cannot drift from the definitions. After a change of the
//! file, `OSC2CR_BLESS=1 cargo test -p osc2cr-osi --test tests generated` rewrites it.

use std::path::{Path, PathBuf};

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// prost-build's output for `osi3.proto`, written into `out`.
fn generate(out: &Path) {
    let proto = crate_dir().join("proto");
    let fds = protox::compile([proto.join("osi3.proto")], [&proto]).expect("protox compiles osi3.proto");
    std::fs::create_dir_all(out).expect("output folder");
    prost_build::Config::new().out_dir(out).btree_map(["."]).compile_fds(fds).expect("prost-build generates the types");
}

#[test]
fn the_checked_in_types_are_prost_builds_output_for_the_proto_files() {
    let fresh = std::env::temp_dir().join(format!("osc2cr-osi-gen-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&fresh);
    generate(&fresh);
    assert_eq!(testkit::assert_generated(&fresh, &crate_dir().join("src/generated")), ["osi3.rs"]);
    let _ = std::fs::remove_dir_all(&fresh);
}

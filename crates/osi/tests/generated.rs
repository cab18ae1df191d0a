//! The Rust types of the OSI messages (`src/generated/osi3.rs`) are exactly what prost-build
//! makes of the OSI 3.5.0 `.proto` files in `proto/`, compiled into a descriptor set by protox
//! (a protobuf compiler in Rust: no `protoc` needed): they are regenerated here and compared byte
//! for byte, so the checked-in code cannot drift from the definitions. After a change of the
//! files, `OSC2CR_BLESS=1 cargo test -p osc2cr-osi --test tests generated` rewrites it.

use std::path::{Path, PathBuf};

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// prost-build's output for `osi_groundtruth.proto` and its imports, written into `out`.
fn generate(out: &Path) {
    let proto = crate_dir().join("proto");
    let fds = protox::compile([proto.join("osi_groundtruth.proto")], [&proto]).expect("protox compiles the OSI files");
    std::fs::create_dir_all(out).expect("output folder");
    prost_build::Config::new()
        .out_dir(out)
        // the OSI files' comments are long prose with code-like indentation: rustdoc would take
        // them for doctests; the .proto files beside the code are the documentation
        .disable_comments(["."])
        .btree_map(["."])
        .compile_fds(fds)
        .expect("prost-build generates the types");
}

#[test]
fn the_checked_in_types_are_prost_builds_output_for_the_proto_files() {
    let fresh = std::env::temp_dir().join(format!("osc2cr-osi-gen-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&fresh);
    generate(&fresh);
    assert_eq!(testkit::assert_generated(&fresh, &crate_dir().join("src/generated")), ["osi3.rs"]);
    let _ = std::fs::remove_dir_all(&fresh);
}

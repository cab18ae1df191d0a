//! `osc2cr map` through the binary: every corpus map exits 0 and its output passes
//! cr_check.py --map-only (one batch); bad input exits 2 naming file, line and column.

use std::path::Path;
use std::process::Command;

fn osc2cr() -> Command {
    Command::new(env!("CARGO_BIN_EXE_osc2cr"))
}

fn out_dir(tag: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("osc2cr-cli-map-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_corpus_map_converts_and_passes_cr_check() {
    let files = testkit::corpus_files("xodr");
    if files.is_empty() {
        return;
    }
    let dir = out_dir("corpus");
    let mut outs = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let out = dir.join(format!("{i:02}_{}.xml", f.file_stem().unwrap().to_string_lossy()));
        let o = osc2cr().arg("map").arg(f).arg("-o").arg(&out).output().unwrap();
        assert!(o.status.success(), "{}: {}", f.display(), String::from_utf8_lossy(&o.stderr));
        outs.push(out);
    }
    let results = testkit::cr_check(&outs, &["--map-only"]);
    let failed: Vec<String> = results.iter().filter(|r| !r.ok).map(|r| r.summary()).collect();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

#[test]
fn example_map_is_byte_identical_run_to_run() {
    let ex = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/two_lane_curve.xodr");
    let dir = out_dir("repeat");
    let (a, b) = (dir.join("a.xml"), dir.join("b.xml"));
    for p in [&a, &b] {
        let o = osc2cr().arg("map").arg(&ex).arg("-o").arg(p).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_input_exits_2_with_position_and_writes_nothing() {
    let dir = out_dir("bad");
    let bad = dir.join("bad.xodr");
    std::fs::write(&bad, "<OpenDRIVE>\n  <header revMajor=\"1\" revMinor=\"6\"/>\n  <road id=\"1\" length=\"x\">\n</OpenDRIVE>\n").unwrap();
    let out = dir.join("out.xml");
    let o = osc2cr().arg("map").arg(&bad).arg("-o").arg(&out).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad.xodr:"), "{err}");
    // line:column of the problem (line 3 or 4 depending on what is reported first)
    assert!(err.contains(":3:") || err.contains(":4:"), "{err}");
    assert!(!out.exists());
    // a missing file names the path tried
    let o = osc2cr().arg("map").arg(dir.join("missing.xodr")).arg("-o").arg(&out).output().unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("missing.xodr"));
    let _ = std::fs::remove_dir_all(&dir);
}

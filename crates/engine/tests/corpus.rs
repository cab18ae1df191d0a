//! Every corpus scenario runs without panic, and the traces of those with an esmini reference
//! compare to it with `conformance.py` above a floor (set a little below the measured rate).

use std::path::{Path, PathBuf};
use std::process::Command;

/// Fraction of compared scenarios that must be exact or close (measured 79 of 79; one may
/// slip before this fails).
const FLOOR: f64 = 0.98;

/// Fraction of compared scenarios that must be exact (measured 79 of 79; issue #5 asks 60 %).
const EXACT_FLOOR: f64 = 0.95;

fn shared() -> Option<PathBuf> {
    let p = std::env::var_os("OSC2CR_SHARED").map(PathBuf::from).unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared"));
    if p.join("corpus").exists() {
        Some(p)
    } else if std::env::var_os("CI").is_some() {
        panic!("corpus not found at {} (set OSC2CR_SHARED)", p.display());
    } else {
        eprintln!("corpus not found at {}: test skipped", p.display());
        None
    }
}

#[test]
fn corpus_runs_and_conforms() {
    let Some(shared) = shared() else { return };
    let corpus = shared.join("corpus");
    let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join("engine-corpus-traces");
    let _ = std::fs::remove_dir_all(&out);
    let files = testkit::files_with_ext(&corpus, "xosc");
    let mut ran = 0;
    for f in &files {
        let Ok((scenario, _)) = openscenario::load_scenario(f, &Default::default()) else { continue };
        let net = scenario.road_network.logic_file.as_ref().and_then(|p| opendrive::load(p).ok()).map(|l| l.network);
        let run = engine::simulate(&scenario, net.as_ref(), &engine::Settings::default()).expect("default settings are valid");
        ran += 1;
        let rel = f.strip_prefix(&corpus).expect("under corpus").with_extension("csv");
        let path = out.join(rel);
        std::fs::create_dir_all(path.parent().expect("parent")).expect("mkdir");
        std::fs::write(&path, run.trace.to_csv(&engine::bounding_boxes(&scenario))).expect("write trace");
    }
    assert!(ran > 50, "only {ran} corpus scenarios loaded");
    let status = Command::new("python3")
        .arg(shared.join("tools/conformance.py"))
        .arg("--ref-dir")
        .arg(shared.join("reference/esmini-3.6.0"))
        .arg("--ours-dir")
        .arg(&out)
        .arg("--quiet")
        .arg("--json")
        .arg(out.join("conformance.json"))
        .arg("--fail-under")
        .arg(FLOOR.to_string())
        .status();
    match status {
        Ok(s) => assert!(s.success(), "conformance below {FLOOR}"),
        Err(e) if std::env::var_os("CI").is_none() => {
            eprintln!("python3 not available ({e}): comparison skipped");
            return;
        }
        Err(e) => panic!("python3: {e}"),
    }
    let text = std::fs::read_to_string(out.join("conformance.json")).expect("conformance.json written");
    let json: serde_json::Value = serde_json::from_str(&text).expect("conformance.json is JSON");
    let count = |k: &str| json["counts"][k].as_u64().unwrap_or(0) as f64;
    let compared = count("exact") + count("close") + count("diverged") + count("missing");
    assert!(compared >= 70.0, "only {compared} scenarios compared: {}", json["counts"]);
    let exact = count("exact") / compared;
    assert!(exact >= EXACT_FLOOR, "exact {:.3} below {EXACT_FLOOR}: {}", exact, json["counts"]);
}

//! Every corpus map converts, validates, and its map-only file passes cr_check.py (XSD, both
//! commonroad-io readers, semantic checks), all 35 in one cr_check call.

use crate::common::*;

#[test]
fn every_corpus_map_passes_cr_check() {
    let files = testkit::corpus_files("xodr");
    if files.is_empty() {
        return;
    }
    let dir = std::env::temp_dir().join(format!("osc2cr-map-crcheck-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let date = commonroad::Date::new(2026, 1, 1).unwrap();
    let mut outs = Vec::new();
    for (i, f) in files.iter().enumerate() {
        let net = load(f);
        let r = convert(&net);
        assert!(!r.network.lanelets.is_empty(), "{}: no lanelets", f.display());
        let stem = f.file_stem().unwrap().to_string_lossy().into_owned();
        let sc = map::map_scenario(&net, r, &stem, date).unwrap();
        let problems = sc.validate(None);
        assert!(problems.is_empty(), "{}: {problems:?}", f.display());
        let out = dir.join(format!("{i:02}_{stem}.xml"));
        commonroad::xml::write_atomic(&out, &commonroad::xml::write_map(&sc).unwrap()).unwrap();
        outs.push(out);
    }
    let results = testkit::cr_check(&outs, &["--map-only"]);
    let failed: Vec<String> = results.iter().filter(|r| !r.ok).map(|r| r.summary()).collect();
    let warned: Vec<String> = results.iter().filter(|r| r.n_warnings() > 0).map(|r| r.summary()).collect();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failed.is_empty(), "{} of {} maps fail cr_check:\n{}", failed.len(), results.len(), failed.join("\n"));
    assert!(warned.is_empty(), "cr_check warnings:\n{}", warned.join("\n"));
}

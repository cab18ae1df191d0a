//! The CommonRoad 2024 format on the public corpus: `osc2cr convert --format 2024` next to the
//! 2020a conversion of the same inputs. commonroad-io 2026.1 opens every 2024 output with the
//! three-file reader, and `testkit::compare_2024` finds no difference, object by object, from
//! the 2020a output read by the same library (what is compared, and the 6-decimal tolerance of
//! the XML: `crates/testkit/py/compare_2024.py`). Also: one map per distinct lanelet network,
//! named by its content and referred to by each scenario file; the same bytes whatever the
//! number of threads.
//!
//! `cr_check.py` reads only 2020a XML, so it does not check the 2024 files; they are held to
//! the 2020a files (which pass it, `convert/corpus.rs`) by the comparison.

use crate::common::*;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn convert(input: &Path, out: &Path, extra: &[&str]) -> serde_json::Value {
    let report = out.with_extension("json");
    let mut args = vec!["convert", s(input), "-o", s(out), "--max-variations", "5", "--report", s(&report)];
    args.extend(extra);
    let r = osc2cr(&args);
    assert!(matches!(r.status.code(), Some(0 | 1)), "{}", String::from_utf8_lossy(&r.stderr));
    serde_json::from_slice(&std::fs::read(&report).expect("report")).expect("json")
}

fn path(v: &serde_json::Value) -> PathBuf {
    PathBuf::from(v.as_str().unwrap_or_else(|| panic!("a path, got {v}")))
}

#[test]
fn commonroad_io_reads_every_2024_output_of_the_corpus_as_its_2020a_output() {
    let Some(shared) = testkit::shared_dir() else { return };
    let corpus = shared.join("corpus");
    let (xml_dir, pb_dir) = (tmp("commonroad_2024", "xml"), tmp("commonroad_2024", "pb"));
    let xml = convert(&corpus, &xml_dir, &["-j", "2"]);
    let pb = convert(&corpus, &pb_dir, &["-j", "2", "--format", "2024"]);
    let (xs, ps) = (xml["scenarios"].as_array().expect("scenarios"), pb["scenarios"].as_array().expect("scenarios"));
    assert_eq!(xs.len(), ps.len());
    let mut cases = Vec::new();
    let mut maps_used = BTreeSet::new();
    for (x, p) in xs.iter().zip(ps) {
        assert_eq!(x["input"], p["input"]);
        assert_eq!(x["status"], p["status"], "{}: the formats do not change what converts", x["input"]);
        if p["status"] != "converted" {
            continue;
        }
        let (scenario, dynamic, map) = (path(&p["output"]), path(&p["dynamic"]), path(&p["map"]));
        // the scenario file names its map, which is the file of that name at the top
        let bytes = std::fs::read(&scenario).expect("scenario file");
        let map_id = commonroad::protobuf::map_id_of_scenario(&bytes).expect("a scenario file");
        assert_eq!(map, pb_dir.join(format!("{map_id}.pb")));
        assert!(scenario.to_string_lossy().ends_with("-SC.pb") && dynamic.is_file(), "{}", scenario.display());
        maps_used.insert(map.clone());
        cases.push(testkit::Case2024 { xml: path(&x["output"]), map, scenario, dynamic });
    }
    assert!(cases.len() >= 190, "{} conversions", cases.len());
    // one map per distinct lanelet network: the corpus has far fewer maps than scenarios, and
    // every map file written is some scenario's
    let written: BTreeSet<PathBuf> =
        std::fs::read_dir(&pb_dir).expect("out").flatten().map(|e| e.path()).filter(|p| p.extension().is_some_and(|e| e == "pb")).collect();
    assert_eq!(written, maps_used);
    assert!(maps_used.len() * 2 < cases.len(), "{} maps for {} scenarios", maps_used.len(), cases.len());

    let results = testkit::compare_2024(&cases, &pb_dir);
    let mut counted: BTreeMap<String, u64> = BTreeMap::new();
    let failed: Vec<String> = results.iter().filter(|r| !r.ok).map(|r| r.summary()).collect();
    for r in &results {
        if let Some(m) = r.counted.as_object() {
            for (k, v) in m {
                *counted.entry(k.clone()).or_default() += v.as_u64().unwrap_or(0);
            }
        }
    }
    println!("{} conversions compared, {} maps: {counted:?}", results.len(), maps_used.len());
    assert!(failed.is_empty(), "{} of {} differ:\n{}", failed.len(), results.len(), failed.join("\n"));
    assert!(counted.get("trajectory states").copied().unwrap_or(0) > 10_000, "{counted:?}");
    let _ = std::fs::remove_dir_all(&xml_dir);
    let _ = std::fs::remove_dir_all(&pb_dir);
}

#[test]
fn the_2024_files_are_the_same_bytes_whatever_the_number_of_threads() {
    let Some(shared) = testkit::shared_dir() else { return };
    let input = shared.join("corpus/esmini/xosc");
    let (a, b) = (tmp("commonroad_2024", "j1"), tmp("commonroad_2024", "j2"));
    convert(&input, &a, &["-j", "1", "--format", "2024"]);
    convert(&input, &b, &["-j", "2", "--format", "2024"]);
    let (fa, fb) = (files(&a), files(&b));
    assert_eq!(fa, fb);
    assert!(fa.len() > 100, "{} files", fa.len());
    for f in &fa {
        assert!(std::fs::read(a.join(f)).ok() == std::fs::read(b.join(f)).ok(), "{} differs", f.display());
    }
    let _ = std::fs::remove_dir_all(&a);
    let _ = std::fs::remove_dir_all(&b);
}

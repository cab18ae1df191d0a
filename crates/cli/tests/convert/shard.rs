//! `osc2cr convert --shard K/N`: the N shards of a folder (scenarios, a parameter distribution,
//! a name collision, a sub-folder) together write exactly the files of one unsharded run —
//! same names, same bytes — and each conversion is done by exactly one shard.

use crate::common::*;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A library folder (made afresh as `<tmp>/convert_shard/<name>`): the shipped example, a 3 × 3 distribution over it (converted up to 7),
/// a scenario whose name collides with the distribution's first variation, and a sub-folder.
fn library(name: &str) -> PathBuf {
    let root = testkit::workspace_root().join("examples");
    let lib = tmp("convert_shard", name);
    let scenario = std::fs::read_to_string(root.join("cut_in.xosc")).expect("example");
    let road = std::fs::read(root.join("two_lane_curve.xodr")).expect("example road");
    std::fs::create_dir_all(lib.join("sub")).expect("sub folder");
    for dir in [lib.clone(), lib.join("sub")] {
        std::fs::write(dir.join("cut_in.xosc"), &scenario).expect("write");
        std::fs::write(dir.join("two_lane_curve.xodr"), &road).expect("write");
    }
    std::fs::write(lib.join("speeds_1.xosc"), &scenario).expect("write");
    let dist = r#"<?xml version="1.0" encoding="utf-8"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="2" date="2026-01-02T00:00:00" description="speeds" author="test"/>
  <ParameterValueDistribution>
    <ScenarioFile filepath="cut_in.xosc"/>
    <Deterministic>
      <DeterministicSingleParameterDistribution parameterName="EgoSpeed">
        <DistributionSet><Element value="10"/><Element value="12"/><Element value="15"/></DistributionSet>
      </DeterministicSingleParameterDistribution>
      <DeterministicSingleParameterDistribution parameterName="OvertakerSpeed">
        <DistributionRange stepWidth="2"><Range lowerLimit="20" upperLimit="24"/></DistributionRange>
      </DeterministicSingleParameterDistribution>
    </Deterministic>
  </ParameterValueDistribution>
</OpenSCENARIO>
"#;
    std::fs::write(lib.join("speeds.xosc"), dist).expect("write");
    lib
}

/// Converts `lib` into `out` with `options` and, if given, `--shard K/N`; the files written.
fn convert_shard(lib: &Path, options: &[&str], out: &Path, shard: Option<&str>) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut args = vec!["convert", s(lib), "-o", s(out)];
    args.extend(options);
    if let Some(k) = shard {
        args.extend(["--shard", k]);
    }
    let r = osc2cr(&args);
    assert!(r.status.success(), "{:?}: {}", shard, String::from_utf8_lossy(&r.stderr));
    contents(out)
}

#[test]
fn three_shards_write_exactly_the_unsharded_files() {
    let lib = library("lib");
    let common = ["--max-variations", "7", "-j", "2"];
    let run = |out: &Path, shard: Option<&str>| convert_shard(&lib, &common, out, shard);
    let whole = run(&tmp("convert_shard", "whole"), None);

    // names by the CLI's rule: files in sorted order (cut_in, speeds, speeds_1, sub/cut_in),
    // variations `_k` for k = 1..=7, and `-2` for the second claim on a name
    let mut expected: Vec<PathBuf> = vec!["cut_in.xml".into()];
    expected.extend((1..=7).map(|k| PathBuf::from(format!("speeds_{k}.xml"))));
    expected.push("speeds_1-2.xml".into());
    expected.push(PathBuf::from("sub").join("cut_in.xml"));
    expected.sort();
    assert_eq!(whole.keys().cloned().collect::<Vec<_>>(), expected);

    let mut union = BTreeMap::new();
    let mut sizes = Vec::new();
    for k in 1..=3 {
        let part = run(&tmp("convert_shard", &format!("shard{k}")), Some(&format!("{k}/3")));
        sizes.push(part.len());
        for (name, bytes) in part {
            assert!(union.insert(name.clone(), bytes).is_none(), "{} written by two shards", name.display());
        }
    }
    // 10 conversions at positions 0..9: p mod 3 = 0 → 4, 1 → 3, 2 → 3
    assert_eq!(sizes, vec![4, 3, 3]);
    assert_eq!(union.keys().collect::<Vec<_>>(), whole.keys().collect::<Vec<_>>());
    for (name, bytes) in &whole {
        assert!(union[name] == *bytes, "{} differs between the shard and the whole run", name.display());
    }
}

#[test]
fn three_shards_write_exactly_the_unsharded_files_in_the_2024_format() {
    let lib = library("lib-2024");
    let common = ["--max-variations", "7", "-j", "2", "--format", "2024"];
    let run = |out: &Path, shard: Option<&str>| convert_shard(&lib, &common, out, shard);
    let whole = run(&tmp("convert_shard", "whole-2024"), None);
    // the same names as in 2020a, as a scenario and a dynamic file each, and one map for the
    // one lanelet network of the library (shared by all ten)
    let maps: Vec<&PathBuf> = whole.keys().filter(|p| p.to_string_lossy().starts_with("ZAM_")).collect();
    assert_eq!(maps.len(), 1, "{:?}", whole.keys());
    let mut stems: Vec<String> = vec!["cut_in".into(), "speeds_1-2".into(), "sub/cut_in".into()];
    stems.extend((1..=7).map(|k| format!("speeds_{k}")));
    for stem in &stems {
        for name in [format!("{stem}-SC.pb"), format!("{stem}.pb")] {
            assert!(whole.contains_key(Path::new(&name)), "{name}: {:?}", whole.keys());
        }
    }
    assert_eq!(whole.len(), 2 * stems.len() + 1);

    // every shard writes the map its scenarios refer to; the rest is written by one shard
    let mut union = BTreeMap::new();
    for k in 1..=3 {
        let part = run(&tmp("convert_shard", &format!("shard{k}-2024")), Some(&format!("{k}/3")));
        for (name, bytes) in part {
            let is_map = name.to_string_lossy().starts_with("ZAM_");
            if let Some(earlier) = union.insert(name.clone(), bytes.clone()) {
                assert!(is_map && earlier == bytes, "{} written by two shards", name.display());
            }
        }
    }
    assert_eq!(union, whole);
}

#[test]
fn more_shards_than_work_is_not_an_error_and_a_bad_shard_is() {
    let example = testkit::workspace_root().join("examples/cut_in.xosc");
    let out = tmp("convert_shard", "empty-shard");
    let r = osc2cr(&["convert", s(&example), "-o", s(&out), "--shard", "2/2"]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    assert!(contents(&out).is_empty(), "the only scenario belongs to shard 1");
    for bad in ["0/2", "3/2", "1/0", "half"] {
        let r = osc2cr(&["convert", s(&example), "-o", s(&out), "--shard", bad]);
        assert_eq!(r.status.code(), Some(2), "--shard {bad}");
    }
}

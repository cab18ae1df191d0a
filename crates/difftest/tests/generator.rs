//! The generator is deterministic for a seed, its scenarios are valid for osc2cr, and — when the
//! esmini binary of `../shared/tools/esmini` is there — a handful of them agree with esmini.

use difftest::{generate::generate, roads};

fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("difftest").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("dir");
    d
}

#[test]
fn same_seed_same_bytes_and_scenarios_differ() {
    let dir = tmp("determinism");
    let maps = roads::builtin(&dir).expect("maps");
    for i in 0..50 {
        let a = generate(7, i, &maps);
        let b = generate(7, i, &maps);
        assert_eq!(a, b, "scenario {i}");
    }
    // random access: scenario 40 does not depend on the ones before it
    assert_eq!(generate(7, 40, &maps).xosc, generate(7, 40, &maps).xosc);
    assert_ne!(generate(7, 1, &maps).xosc, generate(7, 2, &maps).xosc);
    assert_ne!(generate(7, 1, &maps).xosc, generate(8, 1, &maps).xosc);
}

#[test]
fn every_generated_scenario_loads_and_runs_in_osc2cr() {
    let dir = tmp("valid");
    let maps = roads::builtin(&dir).expect("maps");
    let mut features = std::collections::BTreeSet::new();
    for i in 0..200 {
        let g = generate(11, i, &maps);
        let path = dir.join(format!("{}.xosc", g.name));
        std::fs::write(&path, &g.xosc).expect("write");
        let traces = difftest::run_osc2cr(&path).unwrap_or_else(|e| panic!("{}: {e}", g.name));
        assert!(!traces.is_empty());
        features.extend(g.features);
    }
    // the grammar reaches every action, condition and Init position kind
    for f in [
        "action:SpeedAction",
        "action:LaneChangeAction",
        "action:LaneOffsetAction",
        "action:TeleportAction",
        "condition:SimulationTimeCondition",
        "condition:TraveledDistanceCondition",
        "condition:SpeedCondition",
        "condition:RelativeDistanceCondition",
        "init:LanePosition",
        "init:RoadPosition",
        "init:WorldPosition",
        "init:RelativeLanePosition",
        "init:RelativeObjectPosition",
        "init:RelativeRoadPosition",
        "edge:rising",
        "condition-delay",
        "priority:override",
        "controller:ACCController/override",
        "controller:ACCController/additive",
    ] {
        assert!(features.contains(f), "{f} never generated");
    }
}

#[test]
fn agrees_with_esmini_on_a_few() {
    let Some(shared) = testkit::shared_dir() else { return };
    let esmini = shared.join("tools/esmini/bin/esmini-3.6.0");
    if !esmini.is_file() {
        assert!(std::env::var_os("CI").is_none(), "CI has the esmini binary in ../shared");
        eprintln!("notice: no esmini binary; comparison skipped");
        return;
    }
    let plan = difftest::Plan { seed: 1, count: 12, out: tmp("esmini"), esmini: Some(esmini), maps: None, max_maps: 0 };
    let outcomes = difftest::run(&plan, |_, _| {}).expect("runs");
    let compared = outcomes.iter().filter(|o| o.verdict.is_some()).count();
    assert_eq!(compared, 12, "every scenario ran in esmini: {outcomes:?}");
    let agree = outcomes.iter().filter(|o| matches!(o.verdict, Some(difftest::compare::Verdict::Exact | difftest::compare::Verdict::Close))).count();
    // measured 9 of these 12 when the tool was written, 11 once ACC drivers were in the grammar
    // and the engine fixes it found were in (only 10 diverges); never fewer
    assert!(agree >= 11, "{agree} of 12 agree: {outcomes:#?}");
}

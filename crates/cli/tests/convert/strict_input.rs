//! Strict by default: a file that refers to what does not exist, or a distribution that cannot
//! be sampled, stops with an error naming file:line:col — exit 2, no output file — and
//! `--lenient` converts it anyway with the problem as a warning. Each case is the shipped
//! example with one reference broken (lines and columns of examples/cut_in.xosc, counted in the
//! file). A problem is placed at the value of the attribute that holds the broken name.

use crate::common::*;

use std::path::{Path, PathBuf};

/// The example copied into a fresh folder with `from` replaced by `to` (exactly once).
fn broken(name: &str, from: &str, to: &str) -> (PathBuf, PathBuf) {
    let dir = tmp("strict_input", name);
    let text = std::fs::read_to_string(example()).expect("example");
    assert_eq!(text.matches(from).count(), 1, "{from:?} occurs once in the example");
    let file = dir.join(format!("{name}.xosc"));
    std::fs::write(&file, text.replace(from, to)).expect("write");
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("road");
    (dir, file)
}

fn xml_files(dir: &Path) -> Vec<PathBuf> {
    std::fs::read_dir(dir).map(|r| r.flatten().map(|e| e.path()).filter(|p| p.extension().is_some_and(|e| e == "xml")).collect()).unwrap_or_default()
}

/// Strict: exit 2, the message names `at` (file:line) and `what`, nothing written. Lenient:
/// converted, the same message among the warnings.
fn rejected_then_lenient(name: &str, from: &str, to: &str, at: &str, what: &str) {
    let (dir, file) = broken(name, from, to);
    let out = dir.join("out");
    let r = osc2cr(&["convert", s(&file), "-o", s(&out)]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert_eq!(r.status.code(), Some(2), "{name}: {err}");
    assert!(err.contains(at) && err.contains(what), "{name}: expected {at} and {what:?} in:\n{err}");
    assert!(err.contains("--lenient"), "{name}: the message says how to go on: {err}");
    assert!(xml_files(&out).is_empty(), "{name}: nothing written");

    let r = osc2cr(&["convert", s(&file), "-o", s(&out), "--lenient", "-v"]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert!(r.status.success(), "{name} --lenient: {err}");
    assert!(err.contains(what), "{name} --lenient: the warning is kept: {err}");
    assert_eq!(xml_files(&out).len(), 1, "{name} --lenient: written");

    // simulate follows the same rule
    let trace = dir.join("trace.csv");
    let r = osc2cr(&["simulate", s(&file), "--trace", s(&trace)]);
    assert_eq!(r.status.code(), Some(2), "{name} simulate: {}", String::from_utf8_lossy(&r.stderr));
    assert!(!trace.exists());
    let r = osc2cr(&["simulate", s(&file), "--trace", s(&trace), "--lenient"]);
    assert!(r.status.success(), "{name} simulate --lenient: {}", String::from_utf8_lossy(&r.stderr));
}

#[test]
fn an_init_action_on_an_undeclared_entity() {
    // line 70: <Private entityRef="Walker"> — renamed to an entity nobody declared; the value
    // starts at column 29
    rejected_then_lenient(
        "init_entity",
        r#"<Private entityRef="Walker">"#,
        r#"<Private entityRef="Walkr">"#,
        "init_entity.xosc:70:29",
        "`Walkr` is not an entity",
    );
}

#[test]
fn an_action_relative_to_an_undeclared_entity() {
    // line 138: the DistanceCondition's position is relative to an entity that does not exist;
    // its entityRef's value is at column 68
    rejected_then_lenient(
        "condition_entity",
        r#"<RelativeObjectPosition entityRef="Ego" dx="0" dy="0"/>"#,
        r#"<RelativeObjectPosition entityRef="Eg0" dx="0" dy="0"/>"#,
        "condition_entity.xosc:138:68",
        "`Eg0` is not an entity",
    );
}

#[test]
fn a_position_on_a_road_the_map_does_not_have() {
    // line 61: the Overtaker starts on road 7 (two_lane_curve.xodr has only road 1); the roadId's
    // value is at column 61
    rejected_then_lenient(
        "missing_road",
        r#"<LanePosition roadId="1" laneId="-1" s="5" offset="0"/>"#,
        r#"<LanePosition roadId="7" laneId="-1" s="5" offset="0"/>"#,
        "missing_road.xosc:61:61",
        "road `7` is not in the road network",
    );
}

#[test]
fn a_position_in_a_lane_the_road_does_not_have() {
    // line 72: the Walker's lane -2 becomes -5 (the road has lanes 1, -1, -2); laneId's value at 72:72
    rejected_then_lenient(
        "missing_lane",
        r#"<LanePosition roadId="1" laneId="-2" s="200" offset="0"/>"#,
        r#"<LanePosition roadId="1" laneId="-5" s="200" offset="0"/>"#,
        "missing_lane.xosc:72:72",
        "has no lane -5",
    );
}

#[test]
fn an_override_of_a_parameter_the_scenario_does_not_declare() {
    let out = tmp("strict_input", "param");
    let r = osc2cr(&["convert", s(&example()), "-o", s(&out), "--param", "EgoSpeeed=10"]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert_eq!(r.status.code(), Some(2), "{err}");
    assert!(err.contains("'EgoSpeeed'") && err.contains("not declared"), "{err}");
    assert!(xml_files(&out).is_empty());
}

/// A stochastic distribution over the example; `body` is its StochasticDistribution content.
fn distribution(name: &str, parameter: &str, body: &str) -> (PathBuf, PathBuf) {
    let (dir, _) = broken(name, "<Private entityRef=\"Walker\">", "<Private entityRef=\"Walker\">");
    let scenario = dir.join(format!("{name}.xosc"));
    std::fs::rename(&scenario, dir.join("cut_in.xosc")).expect("rename");
    let file = dir.join(format!("{name}_set.xosc"));
    std::fs::write(&file, testkit::stochastic_set("cut_in.xosc", parameter, body)).expect("write");
    (dir, file)
}

#[test]
fn a_normal_distribution_with_negative_variance() {
    let (dir, file) = distribution("variance", "EgoSpeed", r#"<NormalDistribution expectedValue="15" variance="-4"/>"#);
    let out = dir.join("out");
    let r = osc2cr(&["convert", s(&file), "-o", s(&out)]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert_eq!(r.status.code(), Some(2), "{err}");
    assert!(err.contains("variance_set.xosc:6:") && err.contains("variance -4 is negative"), "{err}");
    assert!(xml_files(&out).is_empty(), "no variation written");
    let r = osc2cr(&["convert", s(&file), "-o", s(&out), "--lenient"]);
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    assert_eq!(xml_files(&out).len(), 5);
}

#[test]
fn a_distribution_over_a_parameter_the_scenario_does_not_declare() {
    let (dir, file) = distribution("undeclared", "EgoSpeeed", r#"<UniformDistribution><Range lowerLimit="10" upperLimit="20"/></UniformDistribution>"#);
    let out = dir.join("out");
    let r = osc2cr(&["convert", s(&file), "-o", s(&out)]);
    let err = String::from_utf8_lossy(&r.stderr);
    assert_eq!(r.status.code(), Some(2), "{err}");
    assert!(err.contains("'EgoSpeeed'") && err.contains("not declared"), "{err}");
    assert!(xml_files(&out).is_empty(), "no variation written");
}

#[test]
fn help_explains_lenient() {
    for cmd in ["convert", "simulate"] {
        let r = osc2cr(&[cmd, "--help"]);
        let help = String::from_utf8_lossy(&r.stdout);
        assert!(help.contains("--lenient") && help.contains("does not exist"), "{cmd} --help:\n{help}");
    }
}

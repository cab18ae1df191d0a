//! `check` and `convert` agree: every failing input of the test suite — the example broken in
//! each way the cli tests break it (references, roads, lanes, the road network, parameters,
//! distributions, hostile values), the malformed cases of the openscenario crate's tests (not
//! XML, unclosed tags, undeclared parameters, cycles, bad numbers and enumerations, missing
//! attributes), the broken files of `../shared/checker-suite` listed in
//! `data/checker_suite_expectations.tsv`, and corpus scenarios mutated in copies (a road
//! network that is not there, none at all, an entity renamed, the file cut in half) — is run
//! through both, and
//! both give the same verdict: success, or failure. The issue's two cases are among them, and
//! are held to their messages too.

use crate::common::*;

use std::path::{Path, PathBuf};
use std::process::Output;

/// One input: a file (that may not exist) and the `--param` values given to both commands.
struct Case {
    name: String,
    file: PathBuf,
    params: Vec<String>,
}

fn example_text() -> String {
    std::fs::read_to_string(example()).expect("example")
}

/// The example with `from` replaced by `to` (it must occur), beside a copy of its road network.
fn mutated(dir: &Path, name: &str, from: &str, to: &str) -> Case {
    let text = example_text();
    assert!(text.contains(from), "{name}: {from:?} is not in the example");
    written(dir, name, &text.replacen(from, to, 1))
}

/// `text` as `<dir>/<name>.xosc`, beside a copy of the example's road network.
fn written(dir: &Path, name: &str, text: &str) -> Case {
    let file = dir.join(format!("{name}.xosc"));
    std::fs::write(&file, text).expect("write case");
    Case { name: name.to_string(), file, params: Vec::new() }
}

/// The broken inputs built from the repository's example (no `../shared` needed).
fn example_cases(dir: &Path) -> Vec<Case> {
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("road");
    let text = example_text();
    let mut cases = vec![
        Case { name: "missing file".into(), file: dir.join("missing.xosc"), params: Vec::new() },
        written(dir, "not_xml", "this is not XML\n"),
        written(dir, "empty", ""),
        written(dir, "truncated", &text[..text.len() / 2]),
        written(dir, "wrong_root", "<?xml version=\"1.0\"?>\n<NotOpenScenario/>\n"),
    ];
    for (name, from, to) in [
        // the issue's two cases: a LogicFile that does not exist, and no LogicFile at all while
        // the LanePositions remain
        ("logic_file_missing", r#"filepath="two_lane_curve.xodr""#, r#"filepath="no_such_road.xodr""#),
        ("road_network_removed", r#"<LogicFile filepath="two_lane_curve.xodr"/>"#, ""),
        // crates/cli/tests/convert/strict_input.rs
        ("init_entity", r#"<Private entityRef="Walker">"#, r#"<Private entityRef="Walkr">"#),
        ("condition_entity", r#"<RelativeObjectPosition entityRef="Ego" dx="0" dy="0"/>"#, r#"<RelativeObjectPosition entityRef="Eg0" dx="0" dy="0"/>"#),
        ("missing_road", r#"<LanePosition roadId="1" laneId="-1" s="5" offset="0"/>"#, r#"<LanePosition roadId="7" laneId="-1" s="5" offset="0"/>"#),
        ("missing_lane", r#"<LanePosition roadId="1" laneId="-2" s="200" offset="0"/>"#, r#"<LanePosition roadId="1" laneId="-5" s="200" offset="0"/>"#),
        // crates/openscenario/tests/load/malformed.rs, on the example
        ("unclosed_tag", "</Entities>", ""),
        ("undeclared_parameter", r#"value="$EgoSpeed""#, r#"value="$Missing""#),
        ("parameter_cycle", r#"parameterType="double" value="15""#, r#"parameterType="double" value="$EgoSpeed""#),
        ("bad_number", r#"s="30""#, r#"s="12.5.3""#),
        ("expression_error", r#"value="$EgoSpeed""#, r#"value="${2 * (3 + }""#),
        ("bad_enumeration", r#"vehicleCategory="car""#, r#"vehicleCategory="spaceship""#),
        ("missing_attribute", r#" maxSpeed="#, r#" maxSpeeed="#),
        ("unknown_attribute", "<SpeedActionDynamics ", r#"<SpeedActionDynamics colour="red" "#),
        // crates/cli/tests/convert/hostile_inputs.rs
        ("nan_speed", r#"parameterType="double" value="15""#, r#"parameterType="double" value="NaN""#),
        ("deep_expression", r#"value="15""#, &format!(r#"value="${{{}1{}}}""#, "(".repeat(2000), ")".repeat(2000))),
        // a catalog that is not there
        (
            "missing_catalog",
            "<CatalogLocations/>",
            r#"<CatalogLocations><VehicleCatalog><Directory path="no_such_catalogs"/></VehicleCatalog></CatalogLocations>"#,
        ),
    ] {
        cases.push(mutated(dir, name, from, to));
    }
    let missing_catalog = cases.last_mut().expect("a case");
    let text = std::fs::read_to_string(&missing_catalog.file).expect("read");
    let text = text.replacen(
        r#"<ScenarioObject name="Ego">"#,
        r#"<ScenarioObject name="Parked"><CatalogReference catalogName="VehicleCatalog" entryName="car"/></ScenarioObject><ScenarioObject name="Ego">"#,
        1,
    );
    std::fs::write(&missing_catalog.file, text).expect("write");
    // parameters: a value that does not fit its type, a parameter the scenario does not declare
    for (name, param) in [("param_not_a_number", "EgoSpeed=abc"), ("param_undeclared", "EgoSpeeed=10")] {
        cases.push(Case { name: name.into(), file: example(), params: vec![param.into()] });
    }
    // distributions (strict_input.rs): negative variance, an undeclared parameter, a scenario
    // file that is not there
    for (name, scenario, body) in [
        (
            "variance",
            "cut_in.xosc",
            r#"<StochasticDistribution parameterName="EgoSpeed"><NormalDistribution expectedValue="15" variance="-4"/></StochasticDistribution>"#,
        ),
        (
            "undeclared_distribution",
            "cut_in.xosc",
            r#"<StochasticDistribution parameterName="EgoSpeeed"><UniformDistribution><Range lowerLimit="10" upperLimit="20"/></UniformDistribution></StochasticDistribution>"#,
        ),
        (
            "distribution_of_nothing",
            "no_such_scenario.xosc",
            r#"<StochasticDistribution parameterName="EgoSpeed"><UniformDistribution><Range lowerLimit="10" upperLimit="20"/></UniformDistribution></StochasticDistribution>"#,
        ),
    ] {
        let text = format!(
            r#"<?xml version="1.0"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterValueDistribution><ScenarioFile filepath="{scenario}"/>
<Stochastic numberOfTestRuns="2" randomSeed="1">{body}</Stochastic>
</ParameterValueDistribution>
</OpenSCENARIO>"#
        );
        cases.push(written(dir, name, &text));
    }
    std::fs::write(dir.join("cut_in.xosc"), example_text()).expect("scenario of the distributions");
    cases
}

/// The broken files of the checker suite (`data/checker_suite_expectations.tsv`), but for those
/// of the ALKS templates.
fn checker_suite_cases(shared: &Path) -> Vec<Case> {
    let table = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/checker_suite_expectations.tsv")).expect("expectations");
    let mut files: Vec<&str> = table.lines().skip(1).filter_map(|l| l.split('\t').next()).filter(|f| !f.contains("ALKS")).collect();
    files.dedup();
    files.into_iter().map(|f| Case { name: f.to_string(), file: shared.join("checker-suite").join(f), params: Vec::new() }).collect()
}

/// `text` of a file in `folder` with its relative `filepath`/`path` attributes (road network,
/// catalog directories) made absolute, so that a copy elsewhere finds what the original finds.
fn absolutized(text: &str, folder: &Path) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find("path=\"") {
        let (before, after) = rest.split_at(at + "path=\"".len());
        out.push_str(before);
        let end = after.find('"').unwrap_or(after.len());
        let value = &after[..end];
        if value.starts_with('$') || Path::new(value).is_absolute() {
            out.push_str(value);
        } else {
            out.push_str(&folder.join(value).display().to_string());
        }
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// Every corpus scenario, as it is and mutated four ways, written into `dir` (never into
/// `../shared`) with its paths pointing back at the original's maps and catalogs.
fn corpus_cases(dir: &Path) -> Vec<Case> {
    let mut scenarios: Vec<PathBuf> =
        testkit::corpus_files("xosc").into_iter().filter(|f| matches!(convert::classify(f), convert::FileKind::Scenario)).collect();
    scenarios.sort();
    let mut cases = Vec::new();
    for (i, original) in scenarios.iter().enumerate() {
        let Ok(text) = std::fs::read_to_string(original) else { continue };
        let text = absolutized(&text, original.parent().expect("in a folder"));
        let stem = original.file_stem().and_then(|s| s.to_str()).unwrap_or("scenario");
        let mut put = |how: &str, mutated: String| {
            let file = dir.join(format!("{i:03}-{}.xosc", how.replace(' ', "_")));
            std::fs::write(&file, mutated).expect("write case");
            cases.push(Case { name: format!("{stem} ({how})"), file, params: Vec::new() });
        };
        // the copy as it is, to show that copies find what the original finds
        put("as is", text.clone());
        let logic = text.find("<LogicFile").and_then(|a| text[a..].find("/>").map(|b| (a, a + b + 2)));
        if let Some((a, b)) = logic {
            put("road network missing", format!("{}<LogicFile filepath=\"{}\"/>{}", &text[..a], dir.join("no_such_road.xodr").display(), &text[b..]));
            put("no road network", format!("{}{}", &text[..a], &text[b..]));
        }
        if let Some(at) = text.find("entityRef=\"") {
            let at = at + "entityRef=\"".len();
            put("entity renamed", format!("{}NoSuchEntity_{}", &text[..at], &text[at..]));
        }
        let mut half = text.len() / 2;
        while !text.is_char_boundary(half) {
            half -= 1;
        }
        put("cut in half", text[..half].to_string());
    }
    cases
}

fn run(args: &[&str], params: &[String]) -> Output {
    let mut all: Vec<&str> = args.to_vec();
    for p in params {
        all.push("--param");
        all.push(p);
    }
    osc2cr(&all)
}

/// (check's output, convert's output) for `case`; convert stops its engine at 2 s (the verdict
/// of what a run can fail on after that is convert's alone).
fn both(case: &Case, out: &Path) -> (Output, Output) {
    let check = run(&["check", s(&case.file)], &case.params);
    let convert = run(&["convert", s(&case.file), "-o", s(out), "--max-time", "2", "-j", "1"], &case.params);
    (check, convert)
}

fn verdict(o: &Output) -> &'static str {
    if o.status.success() {
        "passes"
    } else {
        "fails"
    }
}

/// Runs every case through both commands, two at a time, and lists the disagreements; the
/// names of the cases both pass are in the second list.
fn disagreements(cases: &[Case], out: &Path) -> (Vec<String>, Vec<String>) {
    let next = std::sync::atomic::AtomicUsize::new(0);
    let found = std::sync::Mutex::new(Vec::new());
    let passed = std::sync::Mutex::new(Vec::new());
    std::thread::scope(|scope| {
        for worker in 0..2 {
            let (next, found, passed) = (&next, &found, &passed);
            scope.spawn(move || loop {
                let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                let Some(case) = cases.get(i) else { break };
                let (check, convert) = both(case, &out.join(format!("w{worker}")));
                if check.status.success() && convert.status.success() {
                    passed.lock().expect("lock").push(case.name.clone());
                }
                // the accepted differences, what is not a fault of the file: a valid scenario
                // without entities (convert has no ego to write a planning problem for) and a
                // catalog in directories that are not there; check warns of each
                let refused = String::from_utf8_lossy(&convert.stderr);
                let not_a_fault =
                    check.status.success() && (refused.contains(convert::NO_EGO) || (refused.contains("catalog '") && refused.contains("(does not exist)")));
                if verdict(&check) != verdict(&convert) && !not_a_fault {
                    let said = format!(
                        "{}: check {} ({:?}), convert {} ({:?})\n  check: {}\n  convert: {}",
                        case.name,
                        verdict(&check),
                        check.status.code(),
                        verdict(&convert),
                        convert.status.code(),
                        String::from_utf8_lossy(&check.stdout)
                            .lines()
                            .chain(String::from_utf8_lossy(&check.stderr).lines())
                            .take(4)
                            .collect::<Vec<_>>()
                            .join(" | "),
                        String::from_utf8_lossy(&convert.stderr).lines().take(3).collect::<Vec<_>>().join(" | "),
                    );
                    found.lock().expect("lock").push(said);
                }
            });
        }
    });
    (found.into_inner().expect("lock"), passed.into_inner().expect("lock"))
}

#[test]
fn check_and_convert_give_every_broken_example_the_same_verdict() {
    let dir = tmp("agree", "example");
    let cases = example_cases(&dir);
    let n = cases.len();
    let (wrong, passed) = disagreements(&cases, &dir.join("out"));
    assert!(n >= 25, "{n} cases");
    assert!(wrong.is_empty(), "{} of {n} cases disagree:\n{}", wrong.len(), wrong.join("\n"));
    // broken, all of them: refused by both (a hint converts anyway, an unknown attribute too)
    assert!(passed.is_empty(), "both passed {passed:?}");
}

#[test]
fn the_issues_two_cases_fail_in_check_with_convert_s_cause() {
    let dir = tmp("agree", "issue");
    let cases = example_cases(&dir);
    let case = |name: &str| cases.iter().find(|c| c.name == name).expect("case");
    // a LogicFile that does not exist: an error at the LogicFile, as convert says it
    let missing = case("logic_file_missing");
    let (check, convert) = both(missing, &dir.join("out"));
    let (said, err) = (String::from_utf8_lossy(&check.stdout), String::from_utf8_lossy(&convert.stderr));
    assert_eq!((check.status.code(), convert.status.code()), (Some(2), Some(2)), "{said}\n{err}");
    let at = format!("{}:13:5: error: the road network (LogicFile)", missing.file.display());
    assert!(said.contains(&at) && said.contains("no_such_road.xodr: no such file"), "{said}");
    assert!(err.contains("logic_file_missing.xosc:13:5: the road network (LogicFile)") && err.contains("no such file"), "{err}");
    // no road network while LanePositions remain: the three positions, errors in both
    let removed = case("road_network_removed");
    let (check, convert) = both(removed, &dir.join("out"));
    let said = String::from_utf8_lossy(&check.stdout);
    assert_eq!((check.status.code(), convert.status.code()), (Some(2), Some(2)), "{said}");
    assert!(said.contains("error: LanePosition on road `1`, but the scenario has no road network"), "{said}");
    assert!(String::from_utf8_lossy(&check.stderr).contains("3 errors"), "{}", String::from_utf8_lossy(&check.stderr));
    // listed once with how many more; each at its own position in the JSON
    let json: serde_json::Value = serde_json::from_slice(&osc2cr(&["check", s(&removed.file), "--json"]).stdout).expect("json");
    let lines: Vec<u64> = json
        .as_array()
        .expect("array")
        .iter()
        .filter(|f| f["severity"] == "error" && f["message"].as_str().is_some_and(|m| m.contains("but the scenario has no road network")))
        .filter_map(|f| f["line"].as_u64())
        .collect();
    assert_eq!(lines.len(), 3, "{json:#}");
}

#[test]
fn check_and_convert_agree_on_the_checker_suite_and_mutated_corpus_files() {
    let Some(shared) = testkit::shared_dir() else { return };
    let dir = tmp("agree", "corpus");
    let mut cases = checker_suite_cases(&shared);
    cases.extend(corpus_cases(&dir));
    let n = cases.len();
    let (wrong, passed) = disagreements(&cases, &dir.join("out"));
    let copies = cases.iter().filter(|c| c.name.ends_with("(as is)")).count();
    let copies_passed = passed.iter().filter(|c| c.ends_with("(as is)")).count();
    eprintln!("{n} cases, {} disagree; {copies_passed} of {copies} unmutated copies pass both, {} mutated ones", wrong.len(), passed.len() - copies_passed);
    assert!(n >= 500, "{n} cases");
    assert!(wrong.is_empty(), "{} of {n} cases disagree:\n{}", wrong.len(), wrong.join("\n"));
    // the copies find their maps and catalogs: most of them convert
    assert!(copies_passed * 10 >= copies * 8, "{copies_passed} of {copies} copies pass: {passed:?}");
}

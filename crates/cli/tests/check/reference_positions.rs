//! Every kind of reference `check` resolves is reported at its own attribute — line and column
//! of the broken value — not at the element that holds it. `data/every_reference/` is a valid
//! scenario (on examples/two_lane_curve.xodr, with a small vehicle catalog) that uses each kind
//! once; each case breaks one of them and looks for the error there.

use crate::common::*;

use std::path::{Path, PathBuf};

fn fixture_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/every_reference")
}

/// The fixture copied into a fresh folder with the map beside it and `from` replaced by `to`
/// (which must occur exactly once); the scenario's path and text.
fn broken(name: &str, from: &str, to: &str) -> (PathBuf, String) {
    let dir = tmp("check_reference_positions", name);
    std::fs::create_dir_all(dir.join("catalogs")).expect("catalog dir");
    std::fs::copy(fixture_dir().join("catalogs/Cars.xosc"), dir.join("catalogs/Cars.xosc")).expect("catalog");
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("map");
    let text = std::fs::read_to_string(fixture_dir().join("every_reference.xosc")).expect("fixture");
    assert_eq!(text.matches(from).count(), 1, "{name}: {from:?} occurs once in the fixture");
    let text = text.replacen(from, to, 1);
    let file = dir.join("every_reference.xosc");
    std::fs::write(&file, &text).expect("write");
    (file, text)
}

/// Line and column (1-based, in characters) of the value of the attribute written `attr="…"` in
/// `needle`, which occurs once in `text`.
fn value_position(text: &str, needle: &str) -> (u64, u64) {
    let at = text.find(needle).unwrap_or_else(|| panic!("{needle:?} not in the text"));
    let quote = needle.find('"').expect("an attribute") + 1;
    let before = &text[..at + quote];
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line as u64, col as u64)
}

/// The 0-based column (in characters) of byte offset `at` in `text`.
fn column_of(text: &str, at: usize) -> u64 {
    text[..at].rsplit('\n').next().map_or(0, |l| l.chars().count()) as u64
}

fn errors(file: &Path) -> Vec<serde_json::Value> {
    let r = osc2cr(&["check", "--json", s(file)]);
    let json: serde_json::Value = serde_json::from_slice(&r.stdout).unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&r.stderr)));
    json.as_array().cloned().unwrap_or_default().into_iter().filter(|f| f["severity"] == "error").collect()
}

#[test]
fn the_fixture_has_no_error() {
    let (file, _) = broken("valid", "<Properties/>", "<Properties/>");
    let found = errors(&file);
    assert!(found.is_empty(), "{found:#?}");
}

/// (case, text in the fixture, its broken form, the broken attribute as written, what the
/// message says)
const CASES: &[(&str, &str, &str, &str, &str)] = &[
    ("init_entity", r#"<Private entityRef="Ego">"#, r#"<Private entityRef="Eg0">"#, r#"entityRef="Eg0""#, "`Eg0` is not an entity"),
    (
        "actor",
        r#"<Actors selectTriggeringEntities="false"><EntityRef entityRef="Other"/>"#,
        r#"<Actors selectTriggeringEntities="false"><EntityRef entityRef="Othr"/>"#,
        r#"entityRef="Othr""#,
        "`Othr` is not an entity",
    ),
    (
        "speed_target_entity",
        r#"<RelativeTargetSpeed entityRef="Ego""#,
        r#"<RelativeTargetSpeed entityRef="Eg0""#,
        r#"entityRef="Eg0""#,
        "`Eg0` is not an entity",
    ),
    (
        "master_entity",
        r#"<SynchronizeAction masterEntityRef="Ego">"#,
        r#"<SynchronizeAction masterEntityRef="Eg0">"#,
        r#"masterEntityRef="Eg0""#,
        "`Eg0` is not an entity",
    ),
    (
        "position_entity",
        r#"<RelativeObjectPosition entityRef="Ego""#,
        r#"<RelativeObjectPosition entityRef="Eg0""#,
        r#"entityRef="Eg0""#,
        "`Eg0` is not an entity",
    ),
    (
        "triggering_entity",
        r#"<TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Ego"/>"#,
        r#"<TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="Eg0"/>"#,
        r#"entityRef="Eg0""#,
        "`Eg0` is not an entity",
    ),
    (
        "condition_entity",
        r#"<RelativeDistanceCondition entityRef="Other""#,
        r#"<RelativeDistanceCondition entityRef="Othr""#,
        r#"entityRef="Othr""#,
        "`Othr` is not an entity",
    ),
    (
        "road",
        r#"<LanePosition roadId="1" laneId="-1" s="30""#,
        r#"<LanePosition roadId="9" laneId="-1" s="30""#,
        r#"roadId="9""#,
        "road `9` is not in the road network",
    ),
    ("lane", r#"<LanePosition roadId="1" laneId="-1" s="150""#, r#"<LanePosition roadId="1" laneId="-7" s="150""#, r#"laneId="-7""#, "has no lane -7"),
    ("storyboard_element", r#"storyboardElementRef="Follow""#, r#"storyboardElementRef="Folow""#, r#"storyboardElementRef="Folow""#, "no event named `Folow`"),
    (
        "parameter_action",
        r#"<ParameterAction parameterRef="Counter">"#,
        r#"<ParameterAction parameterRef="Countr">"#,
        r#"parameterRef="Countr""#,
        "parameter `Countr` is not declared",
    ),
    (
        "parameter_condition",
        r#"<ParameterCondition parameterRef="Counter""#,
        r#"<ParameterCondition parameterRef="Countr""#,
        r#"parameterRef="Countr""#,
        "parameter `Countr` is not declared",
    ),
    (
        "variable_action",
        r#"<VariableAction variableRef="Flag">"#,
        r#"<VariableAction variableRef="Flg">"#,
        r#"variableRef="Flg""#,
        "variable 'Flg' is not declared",
    ),
    (
        "variable_condition",
        r#"<VariableCondition variableRef="Flag""#,
        r#"<VariableCondition variableRef="Flg""#,
        r#"variableRef="Flg""#,
        "variable 'Flg' is not declared",
    ),
    ("catalog", r#"catalogName="Cars""#, r#"catalogName="Trucks""#, r#"catalogName="Trucks""#, "catalog 'Trucks'"),
    ("catalog_entry", r#"entryName="small_car""#, r#"entryName="big_car""#, r#"entryName="big_car""#, "no entry named 'big_car'"),
    (
        "signal_of_a_phase",
        r#"<TrafficSignalState trafficSignalId="1" state="on"/>"#,
        r#"<TrafficSignalState trafficSignalId="5" state="on"/>"#,
        r#"trafficSignalId="5""#,
        "traffic signal `5` is not in the road network",
    ),
    (
        "signal_state_action",
        r#"<TrafficSignalStateAction name="1""#,
        r#"<TrafficSignalStateAction name="6""#,
        r#"name="6""#,
        "traffic signal `6` is not in the road network",
    ),
    (
        "signal_condition",
        r#"<TrafficSignalCondition name="1""#,
        r#"<TrafficSignalCondition name="7""#,
        r#"name="7""#,
        "traffic signal `7` is not in the road network",
    ),
    (
        "controller_action",
        r#"<TrafficSignalControllerAction trafficSignalControllerRef="Main""#,
        r#"<TrafficSignalControllerAction trafficSignalControllerRef="Mian""#,
        r#"trafficSignalControllerRef="Mian""#,
        "controller `Mian` is not declared",
    ),
    (
        "controller_condition",
        r#"<TrafficSignalControllerCondition trafficSignalControllerRef="Main""#,
        r#"<TrafficSignalControllerCondition trafficSignalControllerRef="Mian""#,
        r#"trafficSignalControllerRef="Mian""#,
        "controller `Mian` is not declared",
    ),
    ("controller_reference", r#"reference="Main""#, r#"reference="Mian""#, r#"reference="Mian""#, "controller `Mian` is not declared"),
];

#[test]
fn each_broken_reference_is_reported_at_its_attribute() {
    let mut wrong = Vec::new();
    for (case, from, to, attribute, says) in CASES {
        let (file, text) = broken(case, from, to);
        // the broken attribute, found inside the broken text
        let within = text.find(to).expect("broken text");
        let (line, col) = value_position(&text[within..], attribute);
        let (line, col) = (line + text[..within].matches('\n').count() as u64, if line == 1 { col + column_of(&text, within) } else { col });
        let found = errors(&file);
        let at = found.iter().any(|f| f["line"] == line && f["column"] == col && f["message"].as_str().is_some_and(|m| m.contains(says)));
        if !at {
            let listed: Vec<String> = found.iter().map(|f| format!("{}:{}: {}", f["line"], f["column"], f["message"])).collect();
            wrong.push(format!("{case}: expected {line}:{col} {says:?}, found:\n  {}", listed.join("\n  ")));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn an_assignment_to_a_parameter_the_entry_does_not_declare_is_warned_at_its_parameter_ref() {
    let (file, text) = broken(
        "assignment",
        r#"<CatalogReference catalogName="Cars" entryName="small_car"/>"#,
        r#"<CatalogReference catalogName="Cars" entryName="small_car"><ParameterAssignments><ParameterAssignment parameterRef="Colour" value="red"/></ParameterAssignments></CatalogReference>"#,
    );
    let (line, col) = value_position(&text, r#"parameterRef="Colour""#);
    let r = osc2cr(&["check", "--json", s(&file)]);
    let json: serde_json::Value = serde_json::from_slice(&r.stdout).expect("json");
    let found = json.as_array().cloned().unwrap_or_default();
    assert!(
        found.iter().any(|f| f["severity"] == "warning"
            && f["line"] == line
            && f["column"] == col
            && f["message"].as_str().is_some_and(|m| m.contains("'Colour' does not match any parameter declared by <Vehicle> 'small_car'"))),
        "{found:#?}"
    );
}

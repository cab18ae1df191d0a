//! The rules of the ASAM Quality Checker's OpenSCENARIO XML bundle (asam-ev/qc-openscenarioxml,
//! `checker_bundle_doc.md`) as `osc2cr check` reports them, each with a case that breaks it
//! (reported: an error where the standard says "shall" and esmini cannot run it as meant, a
//! warning where esmini runs it — see each case) and one that keeps it (nothing of the rule).
//! The cases are written here from the rules' descriptions, on `data/every_reference/` (a valid
//! scenario on examples/two_lane_curve.xodr, whose signal is `1`).

use crate::common::*;

use std::path::{Path, PathBuf};

fn fixture_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/every_reference")
}

/// The fixture in a fresh folder with `edits` applied (each `from` must occur once), and the
/// catalog with `catalog_edits`; the scenario's path and text.
fn variant(name: &str, edits: &[(&str, &str)], catalog_edits: &[(&str, &str)]) -> (PathBuf, String) {
    let dir = tmp("check_second_checker_rules", name);
    std::fs::create_dir_all(dir.join("catalogs")).expect("catalog dir");
    std::fs::copy(testkit::workspace_root().join("examples/two_lane_curve.xodr"), dir.join("two_lane_curve.xodr")).expect("map");
    let apply = |mut text: String, edits: &[(&str, &str)]| {
        for (from, to) in edits {
            assert_eq!(text.matches(from).count(), 1, "{name}: {from:?} occurs once");
            text = text.replacen(from, to, 1);
        }
        text
    };
    let catalog = apply(std::fs::read_to_string(fixture_dir().join("catalogs/Cars.xosc")).expect("catalog"), catalog_edits);
    std::fs::write(dir.join("catalogs/Cars.xosc"), catalog).expect("write catalog");
    let text = apply(std::fs::read_to_string(fixture_dir().join("every_reference.xosc")).expect("fixture"), edits);
    let file = dir.join("every_reference.xosc");
    std::fs::write(&file, &text).expect("write");
    (file, text)
}

fn findings(file: &Path) -> Vec<(String, u64, String)> {
    let r = osc2cr(&["check", "--json", s(file)]);
    let json: serde_json::Value = serde_json::from_slice(&r.stdout).unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&r.stderr)));
    json.as_array()
        .cloned()
        .unwrap_or_default()
        .iter()
        .map(|f| {
            (f["severity"].as_str().unwrap_or_default().to_string(), f["line"].as_u64().unwrap_or(0), f["message"].as_str().unwrap_or_default().to_string())
        })
        .collect()
}

/// Line (1-based) of the first occurrence of `needle`.
fn line_of(text: &str, needle: &str) -> u64 {
    let at = text.find(needle).unwrap_or_else(|| panic!("{needle:?} not in the text"));
    text[..at].matches('\n').count() as u64 + 1
}

/// Asserts a finding of `severity` whose message holds `says`, at `line` when given.
fn reported(case: &str, found: &[(String, u64, String)], severity: &str, line: Option<u64>, says: &str) {
    let ok = found.iter().any(|(sev, l, m)| sev == severity && line.is_none_or(|line| *l == line) && m.contains(says));
    assert!(ok, "{case}: expected a {severity} {says:?} at {line:?}, found {found:#?}");
}

/// Asserts that no finding's message holds `says`.
fn not_reported(case: &str, found: &[(String, u64, String)], says: &str) {
    let hits: Vec<_> = found.iter().filter(|(_, _, m)| m.contains(says)).collect();
    assert!(hits.is_empty(), "{case}: nothing of the rule expected, found {hits:#?}");
}

const LIGHT: &str = r#"<Action name="Count">"#;
fn light_action(transition: &str) -> String {
    format!(
        r#"<Action name="Blink"><PrivateAction><AppearanceAction><LightStateAction transitionTime="{transition}"><LightType><VehicleLight vehicleLightType="brakeLights"/></LightType><LightState mode="on"/></LightStateAction></AppearanceAction></PrivateAction></Action>
              {LIGHT}"#
    )
}

#[test]
fn xml_rules_valid_document_root_tag_file_header_version_schema() {
    // xml.valid_xml_document
    let (file, text) = variant("cut_off", &[], &[]);
    std::fs::write(&file, &text[..text.len() / 2]).expect("cut");
    reported("valid_xml_document", &findings(&file), "error", None, "not well-formed XML");
    // xml.root_tag_is_openscenario
    let (file, _) = variant("root", &[("<OpenSCENARIO>", "<OpenScenario>"), ("</OpenSCENARIO>", "</OpenScenario>")], &[]);
    reported("root_tag_is_openscenario", &findings(&file), "error", Some(5), "is not an OpenSCENARIO document");
    // xml.fileheader_is_present
    let (file, _) = variant(
        "no_header",
        &[(r#"<FileHeader revMajor="1" revMinor="3" date="2026-11-27T00:00:00" description="every reference" author="osc2cr"/>"#, "")],
        &[],
    );
    reported("fileheader_is_present", &findings(&file), "error", Some(5), "<FileHeader> is required");
    // xml.version_is_defined: both attributes, unsigned shorts
    let (file, _) = variant("no_minor", &[(r#"revMajor="1" revMinor="3""#, r#"revMajor="1""#)], &[]);
    reported("version_is_defined", &findings(&file), "error", Some(6), "needs the attribute 'revMinor'");
    let (file, _) = variant("bad_major", &[(r#"revMajor="1" revMinor="3""#, r#"revMajor="one" revMinor="3""#)], &[]);
    reported("version_is_defined", &findings(&file), "error", Some(6), "'one' is not a valid unsignedShort");
    // xml.valid_schema
    let (file, text) = variant("schema", &[("<Properties/>\n      </Vehicle>", "<Propertys/>\n      </Vehicle>")], &[]);
    reported("valid_schema", &findings(&file), "error", Some(line_of(&text, "<Propertys/>")), "unknown element <Propertys>");
    // the fixture keeps them all
    let (file, _) = variant("valid", &[], &[]);
    let found = findings(&file);
    assert!(found.iter().all(|(sev, _, _)| sev != "error"), "{found:#?}");
}

#[test]
fn reference_rules() {
    // uniquely_resolvable_entity_references: two entries of one catalog named alike (a warning:
    // esmini takes the first)
    let twice = r#"</Vehicle>
    <Vehicle name="small_car" vehicleCategory="van"><Performance maxSpeed="1" maxAcceleration="1" maxDeceleration="1"/><BoundingBox><Center x="0" y="0" z="0"/><Dimensions width="1" length="1" height="1"/></BoundingBox><Axles><RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.6" positionX="0" positionZ="0.3"/></Axles></Vehicle>"#;
    let (file, _) = variant("catalog_twice", &[], &[("</Vehicle>", twice)]);
    let catalog = file.with_file_name("catalogs").join("Cars.xosc");
    reported("uniquely_resolvable_entity_references", &findings(&catalog), "warning", Some(15), "is named 'small_car' like another <Vehicle>");
    let (file, _) = variant("catalog_once", &[], &[]);
    not_reported("uniquely_resolvable_entity_references", &findings(&file.with_file_name("catalogs").join("Cars.xosc")), "like another");

    // resolvable_signal_id_in_traffic_signal_state_action
    let (file, text) = variant("signal", &[(r#"<TrafficSignalStateAction name="1""#, r#"<TrafficSignalStateAction name="42""#)], &[]);
    reported("resolvable_signal_id", &findings(&file), "error", Some(line_of(&text, r#"name="42""#)), "traffic signal `42` is not in the road network");
    // resolvable_traffic_signal_controller_by_traffic_signal_controller_ref
    let (file, text) = variant(
        "controller",
        &[(r#"<TrafficSignalControllerAction trafficSignalControllerRef="Main""#, r#"<TrafficSignalControllerAction trafficSignalControllerRef="Side""#)],
        &[],
    );
    reported("resolvable_traffic_signal_controller", &findings(&file), "error", Some(line_of(&text, r#""Side""#)), "controller `Side` is not declared");
    // valid_actor_reference_in_private_actions: private actions need an actor …
    let no_actor = (r#"<Actors selectTriggeringEntities="false"><EntityRef entityRef="Other"/></Actors>"#, r#"<Actors selectTriggeringEntities="false"/>"#);
    let (file, text) = variant("no_actor", &[no_actor], &[]);
    reported("valid_actor_reference", &findings(&file), "error", Some(line_of(&text, r#"<ManeuverGroup name="Group""#)), "has private actions");
    // … unless the triggering entities are the actors
    let (file, _) = variant("triggering_actors", &[(no_actor.0, r#"<Actors selectTriggeringEntities="true"/>"#)], &[]);
    not_reported("valid_actor_reference", &findings(&file), "has private actions");
    // resolvable_entity_references
    let (file, text) = variant("entity", &[(r#"<RelativeDistanceCondition entityRef="Other""#, r#"<RelativeDistanceCondition entityRef="Nobody""#)], &[]);
    reported("resolvable_entity_references", &findings(&file), "error", Some(line_of(&text, "Nobody")), "`Nobody` is not an entity");
    // resolvable_variable_reference
    let (file, text) = variant("variable", &[(r#"<VariableCondition variableRef="Flag""#, r#"<VariableCondition variableRef="Flags""#)], &[]);
    reported("resolvable_variable_reference", &findings(&file), "error", Some(line_of(&text, "Flags")), "variable 'Flags' is not declared");
    // resolvable_storyboard_element_reference: the name, of its type, once
    let (file, text) = variant("element", &[(r#"storyboardElementRef="Follow""#, r#"storyboardElementRef="Folow""#)], &[]);
    reported("resolvable_storyboard_element_reference", &findings(&file), "error", Some(line_of(&text, "Folow")), "no event named `Folow`");
    let (file, text) = variant(
        "element_type",
        &[(r#"storyboardElementType="event" storyboardElementRef="Follow""#, r#"storyboardElementType="action" storyboardElementRef="Follow""#)],
        &[],
    );
    reported("resolvable_storyboard_element_reference", &findings(&file), "error", Some(line_of(&text, r#""action""#)), "no action named `Follow`");
    let (file, text) = variant("element_twice", &[(r#"<Event name="Later""#, r#"<Event name="Follow""#)], &[]);
    reported(
        "resolvable_storyboard_element_reference",
        &findings(&file),
        "warning",
        Some(line_of(&text, r#"storyboardElementRef="Follow""#)),
        "`Follow` names 2 events",
    );
    // unique_element_names_on_same_level: two events of one maneuver named alike (the case above) …
    reported(
        "unique_element_names_on_same_level",
        &findings(&file),
        "warning",
        Some(line_of(
            &text,
            r#"<Event name="Follow" priority="override">
              <Action name="Stop">"#,
        )),
        "is named 'Follow' like another <Event>",
    );
    // … while a name may be used again under another parent
    let (file, _) = variant("names_elsewhere", &[(r#"<Action name="Stop">"#, r#"<Action name="Count">"#)], &[]);
    not_reported("unique_element_names_on_same_level", &findings(&file), "like another");
}

#[test]
fn parameter_and_data_type_rules() {
    // valid_parameter_declaration_in_catalogs: a parameter the entry does not declare, and one
    // without a default (warnings: a catalog read alone may use its referrers' parameters)
    let (file, _) = variant(
        "catalog_parameters",
        &[],
        &[(
            r#"<Performance maxSpeed="50""#,
            r#"<ParameterDeclarations><ParameterDeclaration name="Colour" parameterType="string" value=""/></ParameterDeclarations><Performance maxSpeed="$TopSpeed""#,
        )],
    );
    let catalog = findings(&file.with_file_name("catalogs").join("Cars.xosc"));
    reported("valid_parameter_declaration_in_catalogs", &catalog, "warning", Some(7), "'$TopSpeed' is not declared in this catalog");
    reported("valid_parameter_declaration_in_catalogs", &catalog, "warning", Some(7), "'Colour' has no default value");
    assert!(catalog.iter().all(|(sev, _, _)| sev != "error"), "{catalog:#?}");

    // allowed_operators: what esmini evaluates beyond the grammar is a warning, what nothing can
    // evaluate an error, the grammar's operators nothing
    let (file, text) = variant("operators", &[(r#"<AbsoluteTargetSpeed value="0"/>"#, r#"<AbsoluteTargetSpeed value="${abs(-2) + pow(2, 2)}"/>"#)], &[]);
    reported("allowed_operators", &findings(&file), "warning", Some(line_of(&text, "abs(")), "function 'abs' is not in the standard's expression grammar");
    not_reported("allowed_operators", &findings(&file), "function 'pow'");
    let (file, text) = variant("bad_operator", &[(r#"<AbsoluteTargetSpeed value="0"/>"#, r#"<AbsoluteTargetSpeed value="${2 ^ 3}"/>"#)], &[]);
    reported("allowed_operators", &findings(&file), "error", Some(line_of(&text, "2 ^ 3")), "in expression");
    let (file, _) = variant(
        "standard_operators",
        &[(r#"<AbsoluteTargetSpeed value="0"/>"#, r#"<AbsoluteTargetSpeed value="${round(7 / 2) * 2 - 1 % 1 + sqrt(floor(ceil(4)))}"/>"#)],
        &[],
    );
    not_reported("allowed_operators", &findings(&file), "expression grammar");

    // non_negative_transition_time_in_light_state_action
    let (file, text) = variant("transition", &[(LIGHT, &light_action("-1"))], &[]);
    reported("non_negative_transition_time", &findings(&file), "error", Some(line_of(&text, r#"transitionTime="-1""#)), "transitionTime");
    let (file, _) = variant("transition_ok", &[(LIGHT, &light_action("0"))], &[]);
    not_reported("non_negative_transition_time", &findings(&file), "transitionTime");
    // positive_duration_in_phase
    let (file, text) = variant("phase", &[(r#"<Phase name="go" duration="10">"#, r#"<Phase name="go" duration="-10">"#)], &[]);
    reported("positive_duration_in_phase", &findings(&file), "error", Some(line_of(&text, r#"duration="-10""#)), "duration");
    let (file, _) = variant("phase_ok", &[], &[]);
    not_reported("positive_duration_in_phase", &findings(&file), "the standard requires duration");
}

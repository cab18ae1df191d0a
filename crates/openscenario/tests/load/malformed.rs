//! Malformed inputs fail with the right kind, message and location.

use crate::common;

use crate::common::{car, pos_of, scenario, teleport, temp_dir};
use openscenario::{load, load_str, Error, ErrorKind, LoadOptions};
use std::path::Path;

fn fail(text: &str) -> Error {
    match load_str(Path::new("/virtual/test.xosc"), text, &LoadOptions::default()) {
        Err(e) => e,
        Ok(_) => panic!("expected an error"),
    }
}

fn at(e: &Error) -> (u32, u32) {
    (e.location.line, e.location.col)
}

/// `e` is of `kind`, its message holds `fragment`, and it stands at `position` (line, column).
fn assert_error(e: &Error, kind: ErrorKind, fragment: &str, position: (u32, u32)) {
    assert_eq!(e.kind, kind, "{e}");
    assert!(e.message.contains(fragment), "{e}");
    assert_eq!(at(e), position, "{e}");
}

/// The one problem of a file that loads (what esmini reads its own way: an error unless lenient).
fn problem(text: &str) -> openscenario::Diagnostic {
    match load_str(Path::new("/virtual/test.xosc"), text, &LoadOptions::default()) {
        Ok(l) => {
            assert_eq!(l.problems.len(), 1, "{:?}", l.problems);
            l.problems[0].clone()
        }
        Err(e) => panic!("expected a problem, not an error: {e}"),
    }
}

#[test]
fn unclosed_tag() {
    let text = scenario("", "", r#"<ScenarioObject name="Ego">"#, "", "");
    let e = fail(&text);
    assert_eq!(e.kind, ErrorKind::Xml);
    assert!(e.message.contains("not well-formed XML"), "{e}");
    // The parser notices at the closing tag of the parent.
    assert_eq!(e.location.line, pos_of(&text, "</Entities>").0, "{e}");
    assert!(e.to_string().starts_with("/virtual/test.xosc:"), "{e}");
}

#[test]
fn undeclared_parameter() {
    let text = scenario("", "", &car("Ego"), &teleport("Ego", "$Missing"), "");
    assert_error(&fail(&text), ErrorKind::UndeclaredParameter, "$Missing is not declared", pos_of(&text, "$Missing"));
}

#[test]
fn undeclared_parameter_inside_expression() {
    let text = scenario("", "", &car("Ego"), &teleport("Ego", "${1 + $Nope}"), "");
    // Column of `$Nope` inside the attribute value.
    assert_error(&fail(&text), ErrorKind::UndeclaredParameter, "$Nope", pos_of(&text, "$Nope}"));
}

#[test]
fn parameter_cycle() {
    let params = r#"<ParameterDeclaration name="A" parameterType="double" value="$B"/>
    <ParameterDeclaration name="B" parameterType="double" value="${$A + 1}"/>"#;
    let text = scenario(params, "", &car("Ego"), &teleport("Ego", "$A"), "");
    assert_error(&fail(&text), ErrorKind::ParameterCycle, "A -> B -> A", pos_of(&text, "$B\""));
}

#[test]
fn bad_number() {
    // a problem, read as esmini reads it (C's atof: the leading number)
    let text = scenario("", "", &car("Ego"), &teleport("Ego", "12.5.3"), "");
    let p = problem(&text);
    assert!(p.message.contains("attribute 'x' of <WorldPosition>: expected a number, found '12.5.3'; esmini reads it as 12.5"), "{p}");
    assert_eq!((p.location.line, p.location.col), pos_of(&text, "12.5.3"));
}

#[test]
fn bad_number_through_a_parameter_names_both() {
    let params = r#"<ParameterDeclaration name="X" parameterType="string" value="far"/>"#;
    let text = scenario(params, "", &car("Ego"), &teleport("Ego", "$X"), "");
    let p = problem(&text);
    assert!(p.message.contains("found 'far' (from '$X'); esmini reads it as 0"), "{p}");
    assert_eq!((p.location.line, p.location.col), pos_of(&text, "$X\""));
}

#[test]
fn bad_number_where_esmini_stops_is_an_error() {
    // esmini reads a bounding box with std::stof, which throws on text: no fallback
    let text = scenario("", "", &car("Ego").replace(r#"width="2""#, r#"width="wide""#), "", "");
    let e = fail(&text);
    assert_eq!(e.kind, ErrorKind::Value);
    assert!(e.message.contains("attribute 'width' of <Dimensions>: expected a number, found 'wide'"), "{e}");
}

#[test]
fn expression_error_position() {
    let text = scenario("", "", &car("Ego"), &teleport("Ego", "${2 * (3 + }"), "");
    let e = fail(&text);
    assert_eq!(e.kind, ErrorKind::Expression);
    let (line, col) = pos_of(&text, "${2 * (3 + }");
    // The expression body "2 * (3 + " ends at its column 10; the value starts 2 characters
    // earlier ("${"), so the error is 11 characters after the value's first character.
    assert_eq!(at(&e), (line, col + 11), "{e}");
    assert!(e.message.contains("at column 12"), "{e}");
}

#[test]
fn bad_enumeration_lists_the_choices() {
    let init = r#"<Private entityRef="Ego"><PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="spaceship" value="1" dynamicsDimension="time"/><SpeedActionTarget><AbsoluteTargetSpeed value="1"/></SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction></Private>"#;
    let text = scenario("", "", &car("Ego"), init, "");
    assert_error(&fail(&text), ErrorKind::Value, "expected one of linear, cubic", pos_of(&text, "spaceship"));
}

#[test]
fn an_unknown_vehicle_category_is_esmini_s_default() {
    let text = scenario("", "", &car("Ego").replace("vehicleCategory=\"car\"", "vehicleCategory=\"spaceship\""), "", "");
    let p = problem(&text);
    assert!(p.message.contains("expected one of car, van, truck") && p.message.ends_with("esmini reads it as its default, car"), "{p}");
    assert_eq!((p.location.line, p.location.col), pos_of(&text, "spaceship"));
}

#[test]
fn missing_required_attribute() {
    let text = scenario("", "", &car("Ego").replace(" maxSpeed=\"70\"", ""), "", "");
    assert_error(&fail(&text), ErrorKind::Structure, "<Performance> needs a 'maxSpeed' attribute", pos_of(&text, "<Performance"));
}

#[test]
fn missing_file_names_the_path() {
    let e = load(Path::new("/nonexistent/dir/scenario.xosc"), &LoadOptions::default()).expect_err("error");
    assert_eq!(e.kind, ErrorKind::Io);
    assert!(e.message.contains("/nonexistent/dir/scenario.xosc"), "{e}");
}

#[test]
fn wrong_root_element() {
    assert_error(&fail("<?xml version=\"1.0\"?>\n<NotOpenScenario/>\n"), ErrorKind::Structure, "expected root element <OpenSCENARIO>", (2, 1));
}

fn write_catalog(dir: &Path) {
    let cat = format!(
        r#"<?xml version="1.0"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="0" date="2020-01-01T00:00:00" description="c" author="c"/>
  <Catalog name="Cars">
    {}
  </Catalog>
</OpenSCENARIO>
"#,
        common::VEHICLE
    );
    std::fs::create_dir_all(dir.join("Vehicles")).expect("mkdir");
    std::fs::write(dir.join("Vehicles/CarCatalog.xosc"), cat).expect("write");
}

/// Loads a scenario in a fresh folder `name` beside the catalog `write_catalog` writes, with the
/// one ScenarioObject `entity`: the scenario's text, its folder and the error it fails with.
fn fail_with_catalog(name: &str, entity: &str) -> (String, testkit::ScratchDir, Error) {
    let dir = temp_dir(name);
    write_catalog(&dir);
    let text = scenario("", r#"<VehicleCatalog><Directory path="Vehicles"/></VehicleCatalog>"#, entity, "", "");
    std::fs::write(dir.join("s.xosc"), &text).expect("write");
    let e = load(&dir.join("s.xosc"), &LoadOptions::default()).expect_err("error");
    (text, dir, e)
}

#[test]
fn missing_catalog_entry() {
    let entity = r#"<ScenarioObject name="Ego"><CatalogReference catalogName="Cars" entryName="truck"/></ScenarioObject>"#;
    let (text, _, e) = fail_with_catalog("missing-entry", entity);
    // at the entry's name
    assert_error(&e, ErrorKind::MissingCatalogEntry, "catalog 'Cars'", pos_of(&text, "truck\""));
    assert!(e.message.contains("no entry named 'truck'"), "{e}");
}

#[test]
fn missing_catalog_names_the_directories_tried() {
    let entity = r#"<ScenarioObject name="Ego"><CatalogReference catalogName="Trucks" entryName="car"/></ScenarioObject>"#;
    let (text, dir, e) = fail_with_catalog("missing-catalog", entity);
    // at the catalog's name
    assert_error(&e, ErrorKind::MissingCatalog, "catalog 'Trucks'", pos_of(&text, "Trucks\""));
    assert!(e.message.contains(&dir.join("Vehicles").display().to_string()), "{e}");
}

#[test]
fn truncated_documents_fail_cleanly() {
    let text = scenario("", "", &car("Ego"), &teleport("Ego", "1"), "");
    for cut in [10, 100, text.len() / 2, text.len() - 20] {
        let e = fail(&text[..cut]);
        assert_eq!(e.kind, ErrorKind::Xml, "cut at {cut}: {e}");
    }
}

#[test]
fn a_document_cut_off_is_reported_where_it_ends() {
    let text = scenario("", "", &car("Ego"), &teleport("Ego", "1"), "");
    let cut = &text[..text.len() / 2];
    let e = fail(cut);
    assert_eq!(e.kind, ErrorKind::Xml, "{e}");
    // The end of the cut text: the line count and the length of the last line, by hand.
    let lines: Vec<&str> = cut.split('\n').collect();
    let want = (lines.len() as u32, lines.last().map_or(0, |l| l.chars().count()) as u32 + 1);
    assert_eq!(at(&e), want, "{e}");
    assert_ne!(at(&e), (1, 1), "{e}");
}

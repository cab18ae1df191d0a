//! What the standard allows and esmini runs is never an error: parameter references and
//! expressions are evaluated wherever the standard allows them — a ValueConstraint's bound
//! (`${-$Ego_InitSpeed_Ve0_kph}`, `${$Ego_InitSpeed_Ve0_kph / 3.6}` as the ALKS templates write
//! them), a VariableDeclaration's value (`${$DummyParameter - 4}`) — by the reader's evaluator,
//! in both passes of `osc2cr check` (the schema pass, `validate`, and the reader, `load`). And a
//! catalog read alone, whose entries may use parameters that only a referring scenario
//! declares, can at most warn.

use crate::common;
use openscenario::validate::{validate_str, Finding, Severity};
use openscenario::{load, load_str, Content, LoadOptions};
use std::path::Path;

fn scenario(params: &str, variables: &str) -> String {
    format!(
        r#"<?xml version="1.0"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="t" author="t"/>
  <ParameterDeclarations>{params}</ParameterDeclarations>
  <VariableDeclarations>{variables}</VariableDeclarations>
  <CatalogLocations/>
  <RoadNetwork/>
  <Entities>{}</Entities>
  <Storyboard>
    <Init><Actions/></Init>
    <StopTrigger/>
  </Storyboard>
</OpenSCENARIO>
"#,
        common::car("Ego")
    )
}

fn at_least(findings: &[Finding], severity: Severity) -> Vec<String> {
    findings.iter().filter(|f| f.severity <= severity).map(|f| format!("{}: {}", f.location.line, f.message)).collect()
}

/// The schema pass's errors and the reader's problems and constraint warnings.
fn both_passes(text: &str) -> (Vec<String>, Vec<String>) {
    let schema = at_least(&validate_str(Path::new("/virtual/t.xosc"), text, &[]), Severity::Error);
    let loaded = load_str(Path::new("/virtual/t.xosc"), text, &LoadOptions::default()).expect("loads");
    let reader = loaded.problems.iter().chain(loaded.warnings.iter().filter(|w| w.message.contains("constraint"))).map(ToString::to_string).collect();
    (schema, reader)
}

/// The ALKS templates' form: a speed in km/h and constraints on others computed from it.
const ALKS_LIKE: &str = r#"
    <ParameterDeclaration name="Ego_InitSpeed_Ve0_kph" parameterType="double" value="60">
      <ConstraintGroup><ValueConstraint rule="greaterThan" value="0"/></ConstraintGroup>
    </ParameterDeclaration>
    <ParameterDeclaration name="Lead_RelSpeed_kph" parameterType="double" value="-10">
      <ConstraintGroup>
        <ValueConstraint rule="greaterThan" value="${-$Ego_InitSpeed_Ve0_kph}"/>
        <ValueConstraint rule="lessOrEqual" value="$Ego_InitSpeed_Ve0_kph"/>
      </ConstraintGroup>
    </ParameterDeclaration>
    <ParameterDeclaration name="Lead_Speed_ms" parameterType="double" value="10">
      <ConstraintGroup><ValueConstraint rule="lessThan" value="${$Ego_InitSpeed_Ve0_kph / 3.6}"/></ConstraintGroup>
    </ParameterDeclaration>"#;

#[test]
fn constraint_bounds_may_be_expressions_and_parameters() {
    let (schema, reader) = both_passes(&scenario(ALKS_LIKE, ""));
    assert!(schema.is_empty(), "{schema:#?}");
    assert!(reader.is_empty(), "{reader:#?}");
}

#[test]
fn an_expression_bound_that_does_not_hold_is_still_reported() {
    // 20 m/s is not below 60 km/h / 3.6 = 16.7 m/s
    let (schema, reader) = both_passes(&scenario(
        &ALKS_LIKE.replace(r#"name="Lead_Speed_ms" parameterType="double" value="10""#, r#"name="Lead_Speed_ms" parameterType="double" value="20""#),
        "",
    ));
    assert!(schema.iter().any(|e| e.contains("'Lead_Speed_ms' = '20' satisfies none of its constraint groups")), "{schema:#?}");
    assert!(reader.iter().any(|w| w.contains("'Lead_Speed_ms' = '20' violates its constraints")), "{reader:#?}");
}

#[test]
fn a_bound_whose_expression_fails_is_an_error_at_it() {
    let text = scenario(&ALKS_LIKE.replace("${$Ego_InitSpeed_Ve0_kph / 3.6}", "${$Ego_InitSpeed_kph / 3.6}"), "");
    let (schema, _) = both_passes(&text);
    assert!(schema.iter().any(|e| e.contains("constraint value") && e.contains("$Ego_InitSpeed_kph is not declared")), "{schema:#?}");
}

#[test]
fn a_variable_s_value_may_use_the_global_parameters() {
    let text = scenario(
        r#"<ParameterDeclaration name="DummyParameter" parameterType="double" value="10"/>"#,
        r#"<VariableDeclaration name="Counter" variableType="double" value="${$DummyParameter - 4}"/>
           <VariableDeclaration name="Copy" variableType="double" value="$DummyParameter"/>"#,
    );
    let (schema, reader) = both_passes(&text);
    assert!(schema.is_empty(), "{schema:#?}");
    assert!(reader.is_empty(), "{reader:#?}");
    let loaded = load_str(Path::new("/virtual/t.xosc"), &text, &LoadOptions::default()).expect("loads");
    let Content::Scenario(s) = loaded.content else { panic!("a scenario") };
    let values: Vec<(&str, &str)> = s.variables.iter().map(|v| (v.name.as_str(), v.value.as_str())).collect();
    assert_eq!(values, [("Counter", "6"), ("Copy", "10")]);
}

#[test]
fn a_variable_that_uses_an_undeclared_parameter_is_an_error() {
    let text = scenario("", r#"<VariableDeclaration name="Counter" variableType="double" value="${$Nope - 4}"/>"#);
    let schema = at_least(&validate_str(Path::new("/virtual/t.xosc"), &text, &[]), Severity::Error);
    assert!(schema.iter().any(|e| e.contains("variable 'Counter'") && e.contains("$Nope is not declared")), "{schema:#?}");
    let e = load_str(Path::new("/virtual/t.xosc"), &text, &LoadOptions::default()).expect_err("the reader stops too");
    assert!(e.message.contains("$Nope is not declared"), "{e}");
}

/// A maneuver catalog whose entry uses `$AccRate`, which only the referring scenario declares
/// (esmini's HWManeuvers.xosc does this), and a controller whose `double` parameter defaults to
/// text it only passes on (esmini's followGhost controller).
const CATALOG: &str = r#"<?xml version="1.0"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="t" author="t"/>
  <Catalog name="Maneuvers">
    <Maneuver name="Brake">
      <ParameterDeclarations><ParameterDeclaration name="Target" parameterType="double" value="10"/></ParameterDeclarations>
      <Event name="BrakeEvent" priority="override">
        <Action name="BrakeAction">
          <PrivateAction><LongitudinalAction><SpeedAction>
            <SpeedActionDynamics dynamicsShape="linear" value="$AccRate" dynamicsDimension="rate"/>
            <SpeedActionTarget><AbsoluteTargetSpeed value="$Target"/></SpeedActionTarget>
          </SpeedAction></LongitudinalAction></PrivateAction>
        </Action>
        <StartTrigger/>
      </Event>
    </Maneuver>
  </Catalog>
</OpenSCENARIO>
"#;

#[test]
fn a_catalog_read_alone_warns_for_the_parameters_its_referrers_declare() {
    let dir = common::temp_dir("catalog-alone");
    let file = dir.join("Maneuvers.xosc");
    std::fs::write(&file, CATALOG).expect("write");
    let schema = validate_str(&file, CATALOG, &[]);
    assert!(at_least(&schema, Severity::Error).is_empty(), "{schema:#?}");
    let line = CATALOG.lines().position(|l| l.contains("$AccRate")).expect("use") as u32 + 1;
    assert!(
        schema.iter().any(|f| f.severity == Severity::Warning && f.location.line == line && f.message.contains("'$AccRate' is not declared in this catalog")),
        "{schema:#?}"
    );
    let loaded = load(&file, &LoadOptions::default()).expect("a catalog read alone loads");
    assert!(loaded.problems.is_empty(), "{:?}", loaded.problems);
    assert!(loaded.warnings.iter().any(|w| w.location.line == line && w.message.contains("'Brake' is not read alone")), "{:?}", loaded.warnings);
}

#[test]
fn a_catalog_default_of_the_wrong_type_is_a_warning_there_and_an_error_in_a_scenario() {
    let declaration = r#"<ParameterDeclaration name="FollowMode" parameterType="double" value="time"/>"#;
    let catalog = CATALOG.replace(
        r#"<ParameterDeclaration name="Target" parameterType="double" value="10"/>"#,
        &format!("{declaration}<ParameterDeclaration name=\"Target\" parameterType=\"double\" value=\"10\"/>"),
    );
    let findings = validate_str(Path::new("/virtual/c.xosc"), &catalog, &[]);
    assert!(findings.iter().any(|f| f.severity == Severity::Warning && f.message.contains("'FollowMode' is declared double")), "{findings:#?}");
    assert!(at_least(&findings, Severity::Error).is_empty(), "{findings:#?}");
    let (schema, _) = both_passes(&scenario(declaration, ""));
    assert!(schema.iter().any(|e| e.contains("'FollowMode' is declared double")), "{schema:#?}");
}
